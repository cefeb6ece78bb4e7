#include "experiment/element_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "io/config.hpp"

namespace trapdem {

std::string to_string(const Packing& packing) {
  switch (packing.kind) {
    case PackingKind::dense: return "dense";
    case PackingKind::loose: return "loose";
    case PackingKind::preparation_friction: break;
  }
  return fmt::format("mu_prep={:g}", packing.friction);
}

std::optional<Packing> packing_from_name(std::string_view name) {
  if (name == "dense") return Packing::dense;
  if (name == "loose") return Packing::loose;
  constexpr std::string_view prefix = "mu_prep=";
  if (name.substr(0, prefix.size()) != prefix) return std::nullopt;
  const std::string number(name.substr(prefix.size()));
  char* end = nullptr;
  const double friction = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !(friction >= 0.0 && friction <= 10.0))
    return std::nullopt;
  return Packing::prepared_with_friction(friction);
}

const char* to_string(ElementTestKind kind) { return kind == ElementTestKind::biaxial ? "biaxial" : "triaxial"; }

ElementSetup read_element_setup(Config& c) {
  ElementSetup s;
  ElementSettings& e = s.settings;
  // The test's own keys first: ExperimentConfig::from ends with report_unused() over the whole
  // document, so [element] must have been read by then.
  Config t = c.get_table("element");
  e.kind = t.get_choice("test", "biaxial", {"biaxial", "triaxial"}) == "biaxial" ? ElementTestKind::biaxial
                                                                                 : ElementTestKind::triaxial;
  e.confining = t.get_vector<double>("confining", e.confining, "Pa", Range::open_closed(0.0, 1e9));  // 1 GPa crushes any grain
  if (e.confining.empty()) throw t.error("confining", "at least one confining stress > 0 (Pa)");
  e.particles = t.get_int("particles", e.particles, Range::closed(50, 1e6));  // memory and hours: 4000 is usual
  e.inertial_number = t.get_double("inertial_number", e.inertial_number, "", Range::open_closed(0.0, 0.1));
  e.preparation_inertial_number =
      t.get_double("preparation_inertial_number", e.preparation_inertial_number, "", Range::open_closed(0.0, 0.1));
  e.max_axial_strain = t.get_double("max_axial_strain", e.max_axial_strain, "", Range::open_closed(0.0, 0.5));
  e.row_strain = t.get_double("row_strain", e.row_strain, "", Range::open_closed(0.0, 0.05));
  e.critical_state_window =
      t.get_double("critical_state_window", e.critical_state_window, "", Range::open_closed(0.0, 0.5));
  if (e.critical_state_window > e.max_axial_strain)
    throw t.error("critical_state_window", fmt::format("at most max_axial_strain ({})", e.max_axial_strain));
  if (e.row_strain * 4.0 > e.critical_state_window)
    throw t.error("row_strain", fmt::format("at most a quarter of critical_state_window ({}): phi'_cs averages rows",
                                            e.critical_state_window));
  e.gas_solid_fraction = t.get_double("gas_solid_fraction", e.gas_solid_fraction, "", Range::open_closed(0.0, 0.35));
  e.interior_margin = t.get_double("interior_margin", e.interior_margin, "mean diameters", Range::non_negative());
  e.seed = static_cast<std::uint64_t>(t.get_int("seed", 1, Range::non_negative()));
  std::vector<std::string> default_names;
  for (const Packing& packing : e.packings) default_names.push_back(to_string(packing));
  e.packings.clear();
  for (const std::string& name : t.get_vector<std::string>("packings", default_names)) {
    const std::optional<Packing> packing = packing_from_name(name);
    if (!packing)
      throw t.error("packings", fmt::format("\"dense\", \"loose\" or \"mu_prep=X\" with X a friction coefficient in "
                                            "[0, 10] (the compression's); got \"{}\"", name));
    if (std::find(e.packings.begin(), e.packings.end(), *packing) != e.packings.end())
      throw t.error("packings", fmt::format("each packing once; \"{}\" is named twice", name));
    e.packings.push_back(*packing);
  }
  if (e.packings.empty()) throw t.error("packings", "at least one packing");

  if (!c.is_table("particles"))
    throw InputError(fmt::format("{}: no [particles] table: the element test takes the particles (density, size) "
                                 "and the contact law ([contact]) of a run configuration",
                                 c.source_name()));
  const ExperimentConfig run = ExperimentConfig::from(c);
  s.name = run.name;
  s.material = run.material;
  s.time_step = run.time_step();
  s.skin = run.skin();
  s.max_overlap_fraction = run.numerics.max_overlap_fraction;
  s.threads = run.numerics.threads;
  for (double p : e.confining)
    c.add_derived(fmt::format("derived.element.strain_rate_at_{:.0f}Pa", p), shear_strain_rate(s, p), "1/s");
  return s;
}

namespace {
double rate_for(double inertial_number, const ElementSetup& s, double sigma_c) {
  // I = eps_dot d / sqrt(p / rho_s) (GDR MiDi 2004; da Cruz et al. 2005) solved for eps_dot.
  return inertial_number * std::sqrt(sigma_c / s.material.density) / s.material.sizes.mean_diameter();
}
}  // namespace

double shear_strain_rate(const ElementSetup& s, double sigma_c) {
  return rate_for(s.settings.inertial_number, s, sigma_c);
}
double preparation_strain_rate(const ElementSetup& s, double sigma_c) {
  return rate_for(s.settings.preparation_inertial_number, s, sigma_c);
}

}  // namespace trapdem
