#pragma once
// The virtual element test (issue 17): a specimen of a run configuration's particles and contact
// law in a box of six frictionless walls is prepared dense or loose, compressed isotropically to
// the confining stress by servo walls, then sheared at a constant axial strain rate with the
// lateral stress held by the servo (plane strain: biaxial; axisymmetric stresses: triaxial).
// Gravity is off. docs/element.md describes the procedure, its choices and its outputs.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dem/simulation.hpp"
#include "experiment/element_box.hpp"
#include "experiment/element_config.hpp"
#include "experiment/element_stress.hpp"

namespace trapdem {

using ElementLog = std::function<void(const std::string&)>;
// Called after every step of the shear with the specimen and its axial strain (tools and studies
// that measure more than element.csv holds, e.g. the stress at several depths inside the walls).
using ShearObserver = std::function<void(const Simulation&, const ElementBox&, double axial_strain)>;

struct IsotropicState {
  double solid_fraction = 0.0;   // solid volume / box volume at the confining stress
  double void_ratio = 0.0;       // 1 / solid_fraction - 1
  Vec3 wall_stress;              // Pa per axis, mean over the final window
  Vec3 love_weber_stress;        // Pa, the tensor's diagonal, mean over the same window
  double coordination = 0.0;     // 2 (touching particle pairs) / particles
  double max_axis_error = 0.0;   // largest |sigma_axis - target| / target over the axes (window means)
  std::int64_t steps = 0;        // preparation and compression
  double wall_mean() const { return (wall_stress.x + wall_stress.y + wall_stress.z) / 3.0; }
  double love_weber_mean() const { return (love_weber_stress.x + love_weber_stress.y + love_weber_stress.z) / 3.0; }
};

// A specimen at the confining stress in isotropic equilibrium, ready to shear.
struct ElementSpecimen {
  std::unique_ptr<Simulation> sim;
  ElementBox box;
  Packing packing = Packing::dense;
  double confining = 0.0;        // Pa
  IsotropicState isotropic;
};

// One row of element.csv: means over an interval of axial strain (ElementSettings::row_strain).
struct ElementRow {
  double axial_strain = 0.0;       // (H0 - H) / H0, compression positive
  double volumetric_strain = 0.0;  // (V0 - V) / V0, compression positive (dilation negative)
  Vec3 wall_stress;                // Pa, per axis
  Vec3 love_weber_stress;          // Pa, diagonal of the contact stress tensor
  double deviator = 0.0;           // sigma_axial - sigma_lateral (Pa), from the walls
  double mean_stress = 0.0;        // (sigma_xx + sigma_yy + sigma_zz) / 3 (Pa), from the walls
  double sin_phi = 0.0;            // mobilised (sigma_1 - sigma_3) / (sigma_1 + sigma_3), from the walls
  double coordination = 0.0;       // 2 (touching particle pairs) / particles
  double inertial_number = 0.0;    // eps_dot d_mean / sqrt(mean_stress / rho_s)
  double lateral_error = 0.0;      // largest |sigma_lateral - target| / target over the servo axes
  // The contact stress of the interior (ElementSettings::interior_margin from every wall;
  // interior_contact_stress) and the sin phi it gives, the walls' layers left out.
  Vec3 interior_stress;            // Pa, diagonal
  double interior_sin_phi = 0.0;
};

struct SpecimenResult {
  Packing packing = Packing::dense;
  double confining = 0.0;          // Pa
  double strain_rate = 0.0;        // 1/s, axial
  IsotropicState isotropic;
  std::vector<ElementRow> rows;
  // From the rows (summarise_specimen):
  double phi_peak = 0.0;           // degrees, asin of the peak of sin_phi
  double axial_strain_at_peak = 0.0;
  double phi_cs = 0.0;             // degrees, asin of the mean sin_phi over the last critical_state_window
  double phi_cs_scatter = 0.0;     // degrees, standard deviation of the rows' angles over that window
  double phi_cs_interior = 0.0;    // degrees, as phi_cs from the interior's contact stress
  double psi_peak = 0.0;           // degrees, dilatancy angle at the peak (positive: dilating)
  double max_lateral_error = 0.0;  // over the rows
};

struct ElementResult {
  std::string name;                // the run configuration's
  ElementSettings settings;
  double mean_diameter = 0.0;      // m
  double time_step = 0.0;          // s
  std::vector<SpecimenResult> specimens;  // per confining stress, element.packings in order
};

// The stages, for tests and tools; run_element_test chains them.
ElementSpecimen prepare_specimen(const ElementSetup& setup, const Packing& packing, double confining,
                                 const ElementLog& log = {});
SpecimenResult shear_specimen(ElementSpecimen& specimen, const ElementSetup& setup, const ElementLog& log = {},
                              const ShearObserver& observe = {});
ElementResult run_element_test(const ElementSetup& setup, const ElementLog& log = {});

// Fills the angles of `result` from its rows: phi'_peak, phi'_cs (mean of sin_phi over the rows
// whose axial strain lies in the last `critical_state_window`), the dilatancy angle at the peak
// from the slope of the volumetric strain over +-1 % axial strain around it:
//   sin psi = -d eps_v / (2 d eps_1 - d eps_v)
// (Vermeer & de Borst 1984; plane strain and axisymmetric alike, with eps_v = eps_1 + eps_2 +
// eps_3 compression positive).
void summarise_specimen(SpecimenResult& result, double critical_state_window);

}  // namespace trapdem
