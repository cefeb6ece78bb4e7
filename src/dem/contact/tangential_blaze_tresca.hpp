#pragma once
// Blaze-DEM's tangential law read as the material it makes, stable at any time step: a tangential
// spring (as the Coulomb model's, seed eq. 2) whose force is capped at a contact strength that
// does not depend on F_n (a Tresca limit),
//
//   |F_t| <= S = mu_k (m_i + m_j)/2 u0 / dt_ref        (m_i at a wall)
//
// S is Blaze's viscous force mu_k (m_i + m_j)/2 (u0 / dt_ref) |v_t| / V (tangential_blaze_viscous.hpp)
// at the sliding limit |v_t| = V: a contact sliding at any speed carries S whatever its F_n, and
// with the spin frozen (Blaze's angular damping at its own step: docs/config.md) |v_t| <= V, so S
// is the most it carries. In Blaze's quasi-static regime the viscous coefficient c = mu_k m u0 /
// (dt_ref V) exceeds what stops the slip within one of its steps, and its contacts hold by a
// per-step jitter up to that strength; the direct form run at a step much longer than dt_ref
// makes that jitter grow with dt / dt_ref (docs/config.md gives the measurement). This model keeps
// the strength and drops the jitter; what it leaves out is the factor |v_t| / V < 1 of a contact
// that slides while it also closes or opens.
#include <array>
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/tangential_spring.hpp"
#include "dem/contact/blaze_scales.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct BlazeTrescaTangential {
  static constexpr TangentialModel model = TangentialModel::blaze_tresca;
  static constexpr bool needs_tangential_mass = true;  // the mean mass
  static constexpr bool carries_spring_force = true;
  struct Params {
    double strength_rate = 0.0;  // m/s^2, mu_k u0 / dt_ref: S = strength_rate x mean mass
  };
  // mu_k (Blaze's strength factor) and Blaze-DEM's scales (the rest speed is read as with the
  // viscous form, whose strength this is at the sliding limit).
  static constexpr std::array<LawParameter, 4> parameters{
      kBlazeStrengthFactor, kBlazeReferenceTimeStep, kBlazeVelocityScale, kBlazeRestSpeed};
  static Params params(const ContactLaw& law) {
    return {law.kinetic_friction * law.blaze_velocity_scale / law.reference_time_step};
  }

  [[gnu::always_inline]] static TangentialResponse force(const Params& p, ContactHistory& h, const TangentialInputs& in) {
    const Vec3& vt = in.slip_velocity;
    const double kt = in.stiffness, c_t = in.dashpot;
    Vec3 s = advanced_spring(h.tangential_spring, in.normal, vt, in.dt);
    Vec3 ft = -kt * s - c_t * vt;
    const double strength = p.strength_rate * in.mean_mass;  // N
    const double ft2 = norm2(ft);
    const bool sliding = ft2 > strength * strength;
    if (sliding) {
      ft *= strength / std::sqrt(ft2);
      // The spring keeps what the dashpot does not carry (as the Coulomb model's).
      s = kt > 0.0 ? -(ft + c_t * vt) / kt : Vec3{};
    }
    h.tangential_spring = s;
    return {ft, sliding};
  }
};

}  // namespace trapdem
