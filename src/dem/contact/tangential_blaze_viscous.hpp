#pragma once
// Blaze-DEM's tangential force as its public code has it (ElsevierSoftwareX/SOFTX-D-15-00085,
// V_02_2015/src/Device/Physics/Collision_Response.cuh, Collision_Response_Particle_Particle; the
// wall functions alike): no tangential spring and no Coulomb cap, but a viscous force along the
// slip whose coefficient is set by the time step and the centres' relative speed,
//
//   F_t = -mu_k (m_i + m_j)/2 (u0 / dt_ref) (|v_t| / V) v_t / |v_t|
//       = -mu_k (m_i + m_j)/2 (u0 / dt_ref) v_t / V,
//
// with v_t the tangential relative velocity of the contact points (rotation included), V = |v_i - v_j|
// of the centres (translation only; Blaze takes 1 cm/s when it is exactly 0), u0 = 0.05 cm/s
// (the literal 0.050f in Blaze's cm units) and dt_ref Blaze's time step. |F_t| does not depend on
// F_n: a pressure-independent (Tresca-like) contact strength. At a wall Blaze uses the wall's
// coefficient and the particle's mass (trapdem: m_i, the wall law's kinetic_friction).
//
// The coefficient c = mu_k m u0 / (dt_ref V) grows without bound as V -> 0, and an explicit step
// of a viscous force with c dt / m_t > 2 reverses the slip and amplifies it (Blaze's own runs
// then jitter at V ~ mu_k u0). trapdem bounds the force by what stops the slip within one step,
// m_t |v_t| / dt (m_t: the tangential mass below), so that the contact never reverses its slip and
// never creates energy; with Blaze's dt_ref and a moving contact the bound is not reached.
#include <array>
#include <algorithm>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/blaze_scales.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct BlazeViscousTangential {
  static constexpr TangentialModel model = TangentialModel::blaze_viscous;
  static constexpr bool needs_tangential_mass = true;
  static constexpr bool carries_spring_force = false;  // no spring: the force follows the velocities
  struct Params {
    double strength_rate = 0.0;  // m/s^2, mu_k u0 / dt_ref
    double rest_speed = 0.0;     // m/s, V when the centres' relative speed is exactly 0 (Blaze: 1 cm/s)
  };
  // mu_k (Blaze's strength factor) and Blaze-DEM's scales: its time step and its two speeds.
  static constexpr std::array<LawParameter, 4> parameters{
      kBlazeStrengthFactor, kBlazeReferenceTimeStep, kBlazeVelocityScale, kBlazeRestSpeed};
  static Params params(const ContactLaw& law) {
    return {law.kinetic_friction * law.blaze_velocity_scale / law.reference_time_step, law.blaze_rest_speed};
  }

  [[gnu::always_inline]] static TangentialResponse force(const Params& p, ContactHistory&, const TangentialInputs& in) {
    const double speed = in.centre_speed > 0.0 ? in.centre_speed : p.rest_speed;
    const double blaze = p.strength_rate * in.mean_mass / speed;  // N s/m, Blaze's coefficient
    const double stop = in.tangential_mass / in.dt;              // N s/m, stops the slip within this step
    // Sliding: the slip goes on past this step (the bound is not reached).
    return {-std::min(blaze, stop) * in.slip_velocity, blaze < stop};
  }
};

}  // namespace trapdem
