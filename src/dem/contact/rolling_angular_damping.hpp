#pragma once
// Blaze-DEM's "rolling resistance" as its public code has it (ElsevierSoftwareX/SOFTX-D-15-00085,
// V_02_2015/src/Device/Computing/Integration.cuh, the angular update of each integration kernel:
// `velocity_ang[index] -= velocity_ang[index]*SimParms.Roll_Res` after the torque update): every
// particle's angular velocity is multiplied by (1 - mu_r) at every step, in contact or not. It is
// not a torque, and not proportional to F_n (unlike the seed paper's eq. 5).
//
// Blaze applies the factor once per step of its own time step dt_ref; trapdem applies it at the
// same rate in time, (1 - mu_r)^(dt / dt_ref) per step of dt, so that a run with another step is
// the same material (tests/dem/blaze_law_test.cpp). The contact itself carries no rolling torque.
#include <array>
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/blaze_scales.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

struct AngularDampingRolling {
  static constexpr RollingModel model = RollingModel::angular_damping;
  static constexpr bool has_torque = false;
  static constexpr bool keeps_rolling_spring = false;
  static constexpr bool damps_spin = true;  // Simulation applies spin_retention in the second half kick
  static constexpr bool needs_spin_inertia = false;
  static constexpr bool needs_rolling_inertia(const LawChoices&) { return false; }
  struct Params {};
  // mu_r, first (omega x (1 - mu_r) per reference step, so below 1; mu_r = 0 is off), then
  // Blaze-DEM's time step.
  static constexpr std::array<LawParameter, 2> parameters{{
      {"rolling_friction", &ContactLaw::rolling_friction, "", closed_open(0.0, 1.0),
       "a factor in [0, 1) with rolling_model = \"angular_damping\" (omega is multiplied by 1 - mu_r per reference "
       "step)"},
      kBlazeReferenceTimeStep,
  }};
  static Params params(const ContactLaw&) { return {}; }

  // The factor on every particle's angular velocity per engine step of dt (s): the rolling
  // friction mu_r in [0, 1) applied per reference step dt_ref (s).
  static double spin_retention(const ContactLaw& law, double dt) {
    return std::pow(1.0 - law.rolling_friction, dt / law.reference_time_step);
  }
};

}  // namespace trapdem
