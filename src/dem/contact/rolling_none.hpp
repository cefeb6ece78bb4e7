#pragma once
// No rolling resistance: the contact carries no torque beyond r x F_t.
#include <array>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

struct NoRolling {
  static constexpr RollingModel model = RollingModel::none;
  static constexpr bool has_torque = false;            // the evaluator skips the rolling kinematics
  static constexpr bool keeps_rolling_spring = false;  // pair_histories.hpp
  static constexpr bool damps_spin = false;            // no per-particle angular damping (integrator.hpp)
  static constexpr bool needs_spin_inertia = false;
  static constexpr bool needs_rolling_inertia(const LawChoices&) { return false; }
  struct Params {};
  static constexpr std::array<LawParameter, 0> parameters{};
  static Params params(const ContactLaw&) { return {}; }
};

}  // namespace trapdem
