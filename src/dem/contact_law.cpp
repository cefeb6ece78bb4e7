#include "dem/contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dem/contact/law.hpp"
#include "core/errors.hpp"

namespace trapdem {

bool ContactLaw::uses_reference_time_step() const {
  return tangential_model == TangentialModel::blaze_viscous || tangential_model == TangentialModel::blaze_tresca ||
         (rolling_model == RollingModel::angular_damping && rolling_friction > 0.0);
}

double ContactLaw::damping_restitution() const {
  // Blaze-DEM V_02_2015, src/Input/KSimulationData.cpp (every Set_SpringConstants* function):
  // `if (COR >= 0.30 && COR <= 0.90) COR -= 0.038080;` before c_n is computed from it.
  if (damping_model == DampingModel::restitution_blaze && restitution >= 0.3 && restitution <= 0.9)
    return restitution - 0.03808;
  return restitution;
}

double ContactLaw::damping_ratio() const {
  const double e = damping_restitution();
  if (e >= 1.0) return 0.0;
  const double log_e = std::log(e);
  return -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

namespace {
[[noreturn]] void fail(const std::string& where, const char* key, double value, const char* expected) {
  throw InputError(fmt::format("{}.{} = {}: expected {}", where, key, value, expected));
}
}  // namespace

void ContactLaw::validate(const std::string& where) const {
  if (normal_model == NormalModel::linear) {
    if (!(normal_stiffness > 0.0) || !std::isfinite(normal_stiffness)) fail(where, "normal_stiffness", normal_stiffness, "a positive stiffness in N/m");
    if (!(tangential_stiffness >= 0.0) || !std::isfinite(tangential_stiffness)) fail(where, "tangential_stiffness", tangential_stiffness, "a stiffness >= 0 in N/m");
  } else {
    validate_material(where);
  }
  if (!(restitution > 0.0 && restitution <= 1.0)) fail(where, "restitution", restitution, "a coefficient of restitution in (0, 1]");
  if (!(static_friction >= 0.0)) fail(where, "static_friction", static_friction, "a friction coefficient >= 0");
  if (!(kinetic_friction >= 0.0)) fail(where, "kinetic_friction", kinetic_friction, "a friction coefficient >= 0");
  if (!(rolling_friction >= 0.0)) fail(where, "rolling_friction", rolling_friction, "a rolling friction coefficient >= 0");
  if (!(rolling_damping >= 0.0)) fail(where, "rolling_damping", rolling_damping, "a damping ratio >= 0");
  if (rolling_model == RollingModel::angular_damping && !(rolling_friction < 1.0))
    fail(where, "rolling_friction", rolling_friction,
         "a factor in [0, 1) with rolling_model = \"angular_damping\" (omega is multiplied by 1 - mu_r per reference step)");
  if (uses_reference_time_step()) {
    if (!(reference_time_step > 0.0) || !std::isfinite(reference_time_step))
      fail(where, "reference_time_step", reference_time_step,
           "a positive time step in s (Blaze-DEM's dt: tangential_model = \"blaze_viscous\" or \"blaze_tresca\" and "
           "rolling_model = \"angular_damping\" take their scales from it)");
    if (!(blaze_velocity_scale > 0.0) || !std::isfinite(blaze_velocity_scale))
      fail(where, "blaze_velocity_scale", blaze_velocity_scale, "a positive speed in m/s");
    if (!(blaze_rest_speed > 0.0) || !std::isfinite(blaze_rest_speed))
      fail(where, "blaze_rest_speed", blaze_rest_speed, "a positive speed in m/s");
  }
}

void ContactLaw::validate_material(const std::string& where) const {
  if (!(youngs_modulus > 0.0) || !std::isfinite(youngs_modulus))
    fail(where, "youngs_modulus", youngs_modulus, "a positive Young's modulus in Pa (the Hertz normal model needs it)");
  if (!(poisson_ratio >= 0.0 && poisson_ratio < 0.5)) fail(where, "poisson_ratio", poisson_ratio, "a Poisson's ratio in [0, 0.5)");
}

template <class E>
E parse_choice(std::string_view name) {
  std::string names;
  for (const auto& c : ChoiceTable<E>::values) {
    if (name == c.name) return c.value;
    names += names.empty() ? c.name : fmt::format(", {}", c.name);
  }
  throw InputError(fmt::format("{} '{}': expected one of {}", ChoiceTable<E>::what, name, names));
}
template NormalModel parse_choice<NormalModel>(std::string_view);
template TangentialModel parse_choice<TangentialModel>(std::string_view);
template DampingModel parse_choice<DampingModel>(std::string_view);
template RollingModel parse_choice<RollingModel>(std::string_view);
template RollingLeverArm parse_choice<RollingLeverArm>(std::string_view);
template RollingStiffness parse_choice<RollingStiffness>(std::string_view);

LawChoices law_choices(const ContactLaw& law) {
  LawChoices c;
  c.normal = law.normal_model;
  c.tangential = law.tangential_model;
  c.rolling = law.rolling_friction > 0.0 ? law.rolling_model : RollingModel::none;
  c.lever_arm = law.lever_arm;
  c.rolling_stiffness = law.rolling_stiffness;
  c.rolling_dashpot = c.rolling == RollingModel::elastic_plastic && law.rolling_damping > 0.0;
  return c.canonical();
}

LawParams law_params(const ContactLaw& law, const ContactLaw& particle_law) {
  LawParams p;
  const double damping_scale = NormalModels::visit(law.normal_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.normal) = Model::params(law, particle_law);
    return Model::damping_scale;
  });
  p.damping.factor = 2.0 * damping_scale * law.damping_ratio();
  TangentialModels::visit(law.tangential_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.tangential) = Model::params(law);
    return 0;
  });
  p.mu_r = law.rolling_friction;
  RollingModels::visit(law.rolling_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.rolling) = Model::params(law);
    return 0;
  });
  return p;
}

double spin_retention(const ContactLaw& law, double dt) {
  if (!damps_spin(law_choices(law))) return 1.0;
  return RollingModels::visit(law.rolling_model, [&](auto model) {
    using Model = decltype(model);
    if constexpr (Model::damps_spin)
      return Model::spin_retention(law, dt);
    else
      return 1.0;
  });
}

double contact_time_scale(const ContactLaw& law, const ContactLaw& particle_law, double mass, double radius) {
  return NormalModels::visit(law.normal_model, [&](auto model) {
    return decltype(model)::time_scale(law, particle_law, mass, radius);
  });
}

double critical_time_step(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws, double mass,
                          double radius) {
  double t = contact_time_scale(particle_law, particle_law, mass, radius);
  for (const ContactLaw* law : wall_laws) t = std::min(t, contact_time_scale(*law, particle_law, mass, radius));
  return t;
}

std::string critical_time_step_formula(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws) {
  bool linear = particle_law.normal_model == NormalModel::linear, hertz = !linear;
  for (const ContactLaw* law : wall_laws) {
    linear = linear || law->normal_model == NormalModel::linear;
    hertz = hertz || law->normal_model == NormalModel::hertz;
  }
  if (linear && hertz) return "min(sqrt(m_min/k_max), the Rayleigh time T_R)";
  return linear ? "sqrt(m_min/k_max)" : "the Rayleigh time T_R";
}

std::string describe_stiffness(const ContactLaw& law, const std::string& owner) {
  if (law.normal_model == NormalModel::hertz)
    return fmt::format("Young's modulus of the {} contact law ({:.4g} Pa)", owner, law.youngs_modulus);
  return fmt::format("normal stiffness of the {} contact law ({:.4g} N/m)", owner, law.normal_stiffness);
}

}  // namespace trapdem
