#include "dem/contact_law.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

double ContactLaw::damping_ratio() const {
  if (restitution >= 1.0) return 0.0;
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

void ContactLaw::validate(const std::string& where) const {
  auto fail = [&](const char* key, double value, const char* expected) {
    throw InputError(fmt::format("{}.{} = {}: expected {}", where, key, value, expected));
  };
  if (!(normal_stiffness > 0.0) || !std::isfinite(normal_stiffness)) fail("normal_stiffness", normal_stiffness, "a positive stiffness in N/m");
  if (!(tangential_stiffness >= 0.0) || !std::isfinite(tangential_stiffness)) fail("tangential_stiffness", tangential_stiffness, "a stiffness >= 0 in N/m");
  if (!(restitution > 0.0 && restitution <= 1.0)) fail("restitution", restitution, "a coefficient of restitution in (0, 1]");
  if (!(static_friction >= 0.0)) fail("static_friction", static_friction, "a friction coefficient >= 0");
  if (!(kinetic_friction >= 0.0)) fail("kinetic_friction", kinetic_friction, "a friction coefficient >= 0");
  if (!(rolling_friction >= 0.0)) fail("rolling_friction", rolling_friction, "a rolling friction coefficient >= 0");
  if (!(rolling_damping >= 0.0)) fail("rolling_damping", rolling_damping, "a damping ratio >= 0");
}

RollingModel parse_rolling_model(const std::string& name) {
  if (name == "none") return RollingModel::none;
  if (name == "constant_torque") return RollingModel::constant_torque;
  if (name == "elastic_plastic") return RollingModel::elastic_plastic;
  throw InputError(fmt::format("rolling model '{}': expected one of none, constant_torque, elastic_plastic", name));
}

RollingLeverArm parse_lever_arm(const std::string& name) {
  if (name == "average_radius") return RollingLeverArm::average_radius;
  if (name == "effective_radius") return RollingLeverArm::effective_radius;
  throw InputError(fmt::format("rolling lever arm '{}': expected average_radius or effective_radius", name));
}

RollingStiffness parse_rolling_stiffness(const std::string& name) {
  if (name == "ai2011") return RollingStiffness::ai2011;
  if (name == "tangential") return RollingStiffness::tangential;
  throw InputError(fmt::format("rolling stiffness '{}': expected ai2011 or tangential", name));
}

const char* to_string(RollingModel m) {
  switch (m) {
    case RollingModel::none: return "none";
    case RollingModel::constant_torque: return "constant_torque";
    case RollingModel::elastic_plastic: return "elastic_plastic";
  }
  return "?";
}
const char* to_string(RollingLeverArm a) {
  return a == RollingLeverArm::average_radius ? "average_radius" : "effective_radius";
}
const char* to_string(RollingStiffness s) { return s == RollingStiffness::ai2011 ? "ai2011" : "tangential"; }

ContactConstants make_constants(const ContactLaw& law) {
  ContactConstants c;
  c.kn = law.normal_stiffness;
  c.kt = law.tangential_stiffness;
  c.two_beta = 2.0 * law.damping_ratio();
  c.mu_s = law.static_friction;
  c.mu_k = law.kinetic_friction;
  c.mu_r = law.rolling_friction;
  c.rolling = law.rolling_friction > 0.0 ? static_cast<int>(law.rolling_model) : 0;
  c.effective_lever_arm = law.lever_arm == RollingLeverArm::effective_radius;
  c.rolling_stiffness_from_kt = law.rolling_stiffness == RollingStiffness::tangential;
  c.eta_r = law.rolling_damping;
  c.sqrt_kt_over_kn = std::sqrt(c.kt / c.kn);
  c.needs_rolling_inertia = c.rolling == 2 && c.eta_r > 0.0;
  c.needs_spin_inertia = c.rolling == 1;
  return c;
}

}  // namespace trapdem
