#pragma once
// The motion of rigid bodies (rigid_bodies.hpp) over a step, the counterpart of integrator.hpp's
// for spheres: velocity Verlet for the centre of mass, and for the rotation the angular momentum
// kicked by the torque in the space frame for half a step on either side of the free rotation of
// NO_SQUISH (free_rotation.hpp; Miller et al. 2002; a symmetric top's exact turn). Before the second
// half kick the members' forces are summed onto their bodies; after each, the members' positions, velocities and spins
// follow from their bodies' (a member at arm a from the centre of mass: x + a, v + w x a, w).
// In a rotating frame the centrifugal, Euler and Coriolis forces act at the centre of mass; their
// torque about it (from the field's change over the body: of order the body's size over its
// distance from the axis, ~1e-3 in a centrifuge of 1 m radius with 1 mm grains) is not modelled.
#include "dem/domain.hpp"
#include "dem/integrator.hpp"
#include "dem/particles.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "dem/rotating_frame.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct BodyKick {
  Vec3 gravity;                     // m/s^2
  double half = 0.0;                // s, half the step
  bool rotate = true;               // false: the bodies keep their orientation (freeze_rotation)
  double spin_retention = 1.0;      // the rolling model's spin damping per step (second half kick)
  const FrameKick* frame = nullptr;  // a rotating frame's kick at this half step, or none
};

// The first half kick and the drift over 2 x kick.half: v += h (F/m + g) (in a rotating frame first
// the Coriolis turn and the frame's acceleration at the centre of mass, as frame_first_half_kick),
// L += h T, x += 2h v, and the orientation by the free rotation; then the members placed. Returns,
// as first_half_kick_and_drift does for spheres, the members' displacements since
// `position_at_build` (null: not tracked) and the first member outside the domain's bounded axes.
DriftReport bodies_first_half_kick_and_drift(RigidBodies& bodies, Particles& particles, const BodyKick& kick,
                                             const Vec3* position_at_build, const Domain& domain);

// Each body's force and torque about its centre of mass from its members' forces and torques:
// F = sum f_i, T = sum (a_i x f_i + t_i), with the arms of the last placement.
void reduce_member_loads(RigidBodies& bodies, const Particles& particles);

// The second half kick, each body's loads first reduced from its members' (reduce_member_loads, in
// the same pass): v += h (F/m + g), L = retention (L + h T) (in a rotating frame then the frame's
// acceleration at the centre of mass and the Coriolis turn, as FrameSecondHalfKick); the members'
// velocities and spins follow. Returns 1 when a body's velocity or momentum is not finite.
int bodies_second_half_kick(RigidBodies& bodies, Particles& particles, const BodyKick& kick);

// The members' positions and arms (when `positions`; else the arms of the last placement),
// velocities and spins from their bodies'.
void place_members(RigidBodies& bodies, Particles& particles, bool positions);

}  // namespace trapdem
