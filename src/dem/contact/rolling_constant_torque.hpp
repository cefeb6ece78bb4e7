#pragma once
// Rolling resistance, Ai et al. (2011) type A: a constant torque M = mu_r R |F_n| against the
// relative rolling (the seed paper's eq. 5).
#include <array>
#include <algorithm>
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct ConstantTorqueRolling {
  static constexpr RollingModel model = RollingModel::constant_torque;
  static constexpr bool has_torque = true;
  static constexpr bool keeps_rolling_spring = false;
  static constexpr bool damps_spin = false;
  static constexpr bool needs_spin_inertia = true;
  static constexpr bool needs_rolling_inertia(const LawChoices&) { return false; }
  struct Params {};
  // mu_r, first: a rolling model with mu_r = 0 is off (law_choices).
  static constexpr std::array<LawParameter, 1> parameters{{
      {"rolling_friction", &ContactLaw::rolling_friction, "", closed(0.0, kMaxLawFriction),
       "a rolling friction coefficient >= 0"},
  }};
  static Params params(const ContactLaw&) { return {}; }

  // The torque on body i: the limit mu_r R |F_n| against the relative rolling, bounded by what
  // stops the relative rolling within one step (spin_inertia wr / dt), so that a sphere at rest
  // does not chatter.
  template <LawChoices kLaw>
  [[gnu::always_inline]] static Vec3 torque(const Params&, ContactHistory&, const RollingInputs& in) {
    const Vec3& wr = in.rolling_velocity;
    Vec3 rolling_torque{};
    const double wr_len = norm(wr);
    if (wr_len > 0.0) {
      const double m = std::min(in.limit, in.spin_inertia * wr_len / in.dt);
      rolling_torque = wr * (-m / wr_len);
    }
    return rolling_torque;
  }
};

}  // namespace trapdem
