#pragma once
// What the evaluator (law.hpp) hands the tangential and rolling sub-models: the contact's
// kinematics, the normal force, what the normal model and the damping derived, and the bodies'
// reduced masses and inertias that a model declares it needs (bodies.hpp computes those only).
#include "dem/vec3.hpp"

namespace trapdem {

struct TangentialInputs {
  Vec3 normal;               // unit vector from body j towards body i
  Vec3 slip_velocity;        // m/s, tangential relative velocity of the contact points (rotation included)
  double normal_force;       // N, |F_n|
  double stiffness;          // N/m, k_t of the normal model (constant, or Mindlin's)
  double dashpot;            // N s/m, c_t = c_n sqrt(S_t / S_n)
  double centre_speed;       // m/s, |v_i - v_j| of the centres (translation only)
  double mean_mass;          // kg, (m_i + m_j) / 2; m_i at a wall (only for a model that needs_tangential_mass)
  double tangential_mass;    // kg, what a tangential impulse at the contact point moves (same)
  double dt;                 // s, the engine's time step
};

struct TangentialResponse {
  Vec3 force;    // N, on body i
  bool sliding;  // the contact slides (ContactHistory::kSliding)
};

struct RollingInputs {
  Vec3 normal;              // unit vector from body j towards body i
  Vec3 rolling_velocity;    // rad/s, w_i - w_j less its twist about the normal
  double limit;             // N m, mu_r R |F_n| (seed eq. 5)
  double rolling_friction;  // mu_r
  double lever;             // m, R
  double normal_stiffness;  // N/m, the normal model's (secant) k_n
  double tangential_stiffness;  // N/m, its k_t
  double rolling_inertia;   // kg m^2 (only for a model that needs it)
  double spin_inertia;      // kg m^2 (same)
  double dt;                // s
};

}  // namespace trapdem
