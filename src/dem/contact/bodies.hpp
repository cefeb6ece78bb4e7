#pragma once
// The body reduction: the two bodies of a contact as the law sees them (effective mass and
// radius, lever arms, rolling inertia), written once for particle pairs and particle-wall
// contacts. A wall is a body of infinite mass and inertia that does not rotate and does not
// deform: its terms drop out of each reduction, and the contact point lies on its surface.
#include "dem/contact/models.hpp"

namespace trapdem {

// A sphere as a contact reads it.
struct Body {
  double mass;          // kg
  double radius;        // m
  double inv_inertia;   // 1/(kg m^2)
};

enum class SecondBody { sphere, wall };

struct ContactBodies {
  double effective_mass;     // kg, m* = m_i m_j / (m_i + m_j); m_i at a wall
  double effective_radius;   // m, R* = r_i r_j / (r_i + r_j); r_i at a wall (Hertz, and the effective lever arm)
  double arm_i, arm_j;       // m, centre to contact point (0 for a wall)
  double lever;              // m, rolling lever arm R
  double rolling_inertia;    // kg m^2, Ai et al. (2011) I_r = [1/(I_i + m_i r_i^2) + 1/(I_j + m_j r_j^2)]^-1
  double spin_inertia;       // kg m^2, [1/I_i + 1/I_j]^-1, bounds the constant torque (rolling_constant_torque.hpp)
  double mean_mass;          // kg, (m_i + m_j) / 2; m_i at a wall (tangential_blaze_viscous.hpp)
  double tangential_mass;    // kg, [1/m_i + 1/m_j + a_i^2/I_i + a_j^2/I_j]^-1: what a tangential impulse at the contact point moves
};

// Bodies i and j (j unused for a wall) with overlap delta (m) and centre distance `distance` (m:
// between the centres for a pair, from the centre to the wall's closest point for a wall). The
// quantities the law's models do not declare they need are left 0 (and compiled out).
template <LawChoices kLaw, SecondBody kSecond>
[[gnu::always_inline]] inline ContactBodies reduce_bodies(const Body& i, const Body& j, double overlap,
                                                          double distance) {
  constexpr bool wall = kSecond == SecondBody::wall;
  const double ri = i.radius, rj = j.radius, mi = i.mass, mj = j.mass;
  ContactBodies b;
  b.effective_mass = wall ? mi : mi * mj / (mi + mj);
  // The contact point: the middle of the overlap between spheres, the wall's surface at a wall.
  b.arm_i = wall ? distance : ri - 0.5 * overlap;
  b.arm_j = wall ? 0.0 : rj - 0.5 * overlap;
  const double reach = ri + rj;
  b.effective_radius = wall ? ri : ri * rj / reach;
  b.lever = wall || kLaw.lever_arm == RollingLeverArm::effective_radius ? b.effective_radius : 0.5 * reach;
  // Both bodies' inertias are read whatever the choices (a load under a branch would keep the
  // batch loops from vectorising); the reductions are compiled for the choices that use them.
  using Rolling = RollingModels::Model<kLaw.rolling>;
  using Tangential = TangentialModels::Model<kLaw.tangential>;
  const double inv_ii = i.inv_inertia, inv_ij = j.inv_inertia;
  b.rolling_inertia = !Rolling::needs_rolling_inertia(kLaw) ? 0.0
                      : wall ? 1.0 / inv_ii + mi * ri * ri
                             : 1.0 / (1.0 / (1.0 / inv_ii + mi * ri * ri) + 1.0 / (1.0 / inv_ij + mj * rj * rj));
  b.spin_inertia = !Rolling::needs_spin_inertia ? 0.0 : wall ? 1.0 / inv_ii : 1.0 / (inv_ii + inv_ij);
  b.mean_mass = !Tangential::needs_tangential_mass ? 0.0 : wall ? mi : 0.5 * (mi + mj);
  b.tangential_mass = !Tangential::needs_tangential_mass ? 0.0
                      : wall ? 1.0 / (1.0 / mi + b.arm_i * b.arm_i * inv_ii)
                             : 1.0 / (1.0 / mi + 1.0 / mj + b.arm_i * b.arm_i * inv_ii + b.arm_j * b.arm_j * inv_ij);
  return b;
}

}  // namespace trapdem
