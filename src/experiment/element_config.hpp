#pragma once
// The virtual element test's settings (issue 17): which test, at which confining stresses, with
// how many particles, how fast, and the material taken from a run configuration's [particles] and
// [contact] (read by ExperimentConfig, not parsed again). The test's own keys live in an optional
// [element] table of the same document and are read strictly (docs/element.md lists them).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiment/experiment_config.hpp"

namespace trapdem {

class Config;

enum class ElementTestKind {
  biaxial,   // plane strain: the y walls fixed, the x walls hold the confining stress (the paper's slab)
  triaxial,  // axisymmetric stresses: the x and y walls hold the confining stress
};
const char* to_string(ElementTestKind kind);

// How the specimen's density is set: the isotropic compression from the gas runs with the
// particles' friction and rolling resistance switched off (dense: the spheres slide into a close
// packing), on (loose: the friction holds the first contacts' open structure), or with the
// friction set to a chosen preparation value and no rolling resistance (in between: the density
// grows as the preparation friction falls; Thornton 2000, Salot et al. 2009). The dense and the
// in-between specimens then get their real contact law and are brought to equilibrium again at
// the same stress.
enum class PackingKind { dense, loose, preparation_friction };
struct Packing {
  PackingKind kind = PackingKind::dense;
  double friction = 0.0;  // the compression's contact friction coefficient (preparation_friction only)
  static const Packing dense;
  static const Packing loose;
  static Packing prepared_with_friction(double friction) { return {PackingKind::preparation_friction, friction}; }
  friend bool operator==(const Packing& a, const Packing& b) {
    return a.kind == b.kind && (a.kind != PackingKind::preparation_friction || a.friction == b.friction);
  }
};
inline constexpr Packing Packing::dense{PackingKind::dense, 0.0};
inline constexpr Packing Packing::loose{PackingKind::loose, 0.0};
// "dense", "loose" or "mu_prep=0.1" (element.csv's and element.json's packing column).
std::string to_string(const Packing& packing);

// The packing a name gives ("dense", "loose", "mu_prep=X" with X a friction coefficient in
// [0, 10]); nullopt for any other text.
std::optional<Packing> packing_from_name(std::string_view name);

struct ElementSettings {
  ElementTestKind kind = ElementTestKind::biaxial;
  // Pa. Default: about the mean stress at mid-depth of the trapdoor model at 50 g (docs/element.md:
  // 37-90 kPa depending on the wall friction carried, ~50 kPa in the demo's box).
  std::vector<double> confining{50.0e3};
  std::int64_t particles = 4000;           // in the specimen (docs/element.md: the size and the scatter)
  // Shear at the constant axial strain rate that gives this inertial number at the confining
  // stress, I = eps_dot d_mean / sqrt(sigma_c / rho_s); below 1e-3 is quasi-static (GDR MiDi 2004).
  double inertial_number = 1.0e-3;
  // The isotropic compression from the granular gas is ten times faster (its walls' speed cap):
  // the density is set by the friction during it, not by its rate.
  double preparation_inertial_number = 1.0e-2;
  double max_axial_strain = 0.30;          // end of the shear
  double row_strain = 0.0025;              // axial strain between rows of element.csv (each row an average)
  double critical_state_window = 0.05;     // phi'_cs: the mean over the last this much axial strain
  double gas_solid_fraction = 0.30;        // the random gas the specimen is compressed from
  // The interior whose contact stress element.csv also gives: the box less this many mean
  // diameters along every wall (docs/element.md: the walls' layers).
  double interior_margin = 2.0;
  std::uint64_t seed = 1;                  // placement of the gas (every specimen's)
  // The specimens prepared at each confining stress, in this order ("dense", "loose",
  // "mu_prep=0.2"): the preparation friction sets a specimen's density, hence its peak angle.
  std::vector<Packing> packings{Packing::dense, Packing::loose};
};

// What the element test needs: its settings and the run configuration's material and numerics.
struct ElementSetup {
  std::string name;                        // the run configuration's name
  ElementSettings settings;
  MaterialConfig material;                 // density, sizes, particle-particle law (walls: frictionless)
  double time_step = 0.0;                  // s, as the run configuration's numerics give it
  double skin = 0.0;                       // m
  double max_overlap_fraction = 0.25;
  int threads = 0;                         // numerics.threads (0: all cores)
};

// Reads [element] (strictly), checks that the document has its particles ([particles]) and reads
// the run configuration with ExperimentConfig::from (which reports every unknown key, file:line).
// Throws InputError naming the file, key and what was expected.
ElementSetup read_element_setup(Config& config);

// The strain rate (1/s) of the shear at confining stress `sigma_c` (Pa) and of the preparation.
double shear_strain_rate(const ElementSetup& setup, double sigma_c);
double preparation_strain_rate(const ElementSetup& setup, double sigma_c);

}  // namespace trapdem
