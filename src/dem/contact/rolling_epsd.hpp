#pragma once
// Rolling resistance, Ai et al. (2011) type C (elastic-plastic spring-dashpot, EPSD), eqs. 14-18:
// an incremental spring torque capped at mu_r R |F_n|, with a dashpot while it is below the cap.
#include <array>
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct EpsdRolling {
  static constexpr RollingModel model = RollingModel::elastic_plastic;
  static constexpr bool has_torque = true;
  static constexpr bool keeps_rolling_spring = true;
  static constexpr bool damps_spin = false;
  static constexpr bool needs_spin_inertia = false;
  static constexpr bool needs_rolling_inertia(const LawChoices& law) { return law.rolling_dashpot; }
  struct Params {
    double eta_r = 0.0;  // the dashpot's damping ratio (Ai et al. 2011 use 0.3)
  };
  // mu_r, first: a rolling model with mu_r = 0 is off (law_choices); then the dashpot's eta_r.
  static constexpr std::array<LawParameter, 2> parameters{{
      {"rolling_friction", &ContactLaw::rolling_friction, "", closed(0.0, kMaxLawFriction),
       "a rolling friction coefficient >= 0"},
      {"rolling_damping", &ContactLaw::rolling_damping, "", closed(0.0, kMaxRollingDamping), "a damping ratio >= 0"},
  }};
  static Params params(const ContactLaw& law) { return {law.rolling_damping}; }

  // The torque on body i; updates the history's rolling spring. The stiffness k_r and whether the
  // dashpot is on are the law's choices (rolling_stiffness, rolling_dashpot).
  template <LawChoices kLaw>
  [[gnu::always_inline]] static Vec3 torque(const Params& p, ContactHistory& h, const RollingInputs& in) {
    const double lever = in.lever;
    const double kr = kLaw.rolling_stiffness == RollingStiffness::tangential
                          ? in.tangential_stiffness * lever * lever
                          : 2.25 * in.normal_stiffness * in.rolling_friction * in.rolling_friction * lever * lever;
    const Vec3& n = in.normal;
    const double m_max = in.limit;
    Vec3 mk = h.rolling_spring;
    mk -= dot(mk, n) * n;
    mk -= kr * in.dt * in.rolling_velocity;
    const double mk2 = norm2(mk);
    Vec3 rolling_torque;
    if (mk2 > m_max * m_max) {
      mk *= m_max / std::sqrt(mk2);  // fully mobilised: no dashpot (Ai et al. eq. 18)
      rolling_torque = mk;
    } else {
      rolling_torque = mk;
      if (kLaw.rolling_dashpot)
        rolling_torque -= (p.eta_r * 2.0 * std::sqrt(in.rolling_inertia * kr)) * in.rolling_velocity;
    }
    h.rolling_spring = mk;
    return rolling_torque;
  }
};

}  // namespace trapdem
