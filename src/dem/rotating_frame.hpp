#pragma once
// The body forces of a frame that turns about a fixed axis (a centrifuge's, for a model that flies
// in it), per particle at its own position and velocity (Taylor 1995, "Centrifuges in modelling:
// principles and scale effects", ch. 2 of Geotechnical Centrifuge Technology; Schofield 1980,
// Geotechnique 30(3): 227-268). In the frame turning at omega about the unit axis k through the
// point A, a particle at x with velocity v (relative to the frame) feels, per unit mass:
//   centrifugal  omega^2 r_perp,            r_perp = (x - A) - ((x - A) . k) k, away from the axis;
//   Euler        -(d omega/dt) k x (x - A), against the spin-up, along the direction of travel;
//   Coriolis     -2 omega k x v,            normal to v: it turns v and does no work.
// Centrifugal and Euler depend on the position: they are kicks like gravity. Coriolis is applied
// exactly, as a rotation of v about k by -2 omega dt/2 in each half step (the Boris scheme of
// plasma codes: Boris 1970; Birdsall & Langdon 1991, section 4-3): the first half kick rotates and
// then adds the forces, the second adds the forces and then rotates, so that the step stays
// time-symmetric and second order, and |v| is unchanged by the Coriolis term to round-off.
// The engine keeps the uniform-gravity path as it is when no frame is set (simulation.hpp).
#include <cstddef>
#include <functional>

#include "dem/integrator.hpp"
#include "dem/particles.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The frame's angular velocity (rad/s) and its rate of change (rad/s^2) at a time.
struct FrameSpin {
  double omega = 0.0;
  double alpha = 0.0;
};

struct RotatingFrame {
  Vec3 axis_point;    // m, a point of the axis (model coordinates)
  Vec3 axis{0, 1, 0}; // the angular velocity's direction (normalised when set on a Simulation)
  bool coriolis = true;
  bool euler = true;
  std::function<FrameSpin(double)> spin;  // at the simulated time t (s)

  // m, the part of x - A normal to the axis: the particle's radius vector.
  Vec3 radius_vector(const Vec3& x) const {
    const Vec3 q = x - axis_point;
    return q - dot(q, axis) * axis;
  }
};

// The frame's constants for one half kick of length `half` (s) at one time.
struct FrameKick {
  Vec3 axis_point;
  Vec3 axis;
  double omega2 = 0.0;  // rad^2/s^2
  double alpha = 0.0;   // rad/s^2, 0 when the Euler term is off
  double cos_turn = 1.0, sin_turn = 0.0;  // the Coriolis rotation of v by -2 omega half about the axis

  FrameKick(const RotatingFrame& frame, double time, double half);

  // m/s^2, centrifugal plus Euler at x.
  Vec3 acceleration(const Vec3& x) const {
    const Vec3 q = x - axis_point;
    const Vec3 r = q - dot(q, axis) * axis;
    return omega2 * r - alpha * cross(axis, q);
  }
  // v turned about the axis (Rodrigues' formula), the exact effect of the Coriolis term over the half step.
  Vec3 coriolis_turn(const Vec3& v) const {
    const double along = dot(axis, v);
    return cos_turn * v + sin_turn * cross(axis, v) + ((1.0 - cos_turn) * along) * axis;
  }
};

// Before the standard first half kick and drift (which add F/m and the uniform gravity): the
// Coriolis turn, then the frame's acceleration at the particle's position, for the first n particles.
void frame_first_half_kick(Particles& p, std::size_t n, const FrameKick& frame, double half);

// The second half kick in the frame: the standard one (forces and uniform gravity, and whatever
// else SecondHalfKick does to v and w), then the frame's acceleration at the new position, then
// the Coriolis turn. Returns 1 when the result is not finite.
struct FrameSecondHalfKick {
  SecondHalfKick standard;
  const Vec3* __restrict x;
  FrameKick frame;
  int operator()(std::size_t p) const {
    const int bad = standard(p);
    Vec3& v = standard.v[p];
    v = frame.coriolis_turn(v + standard.half * frame.acceleration(x[p]));
    return bad | (is_finite(v) ? 0 : 1);
  }
};

// J, the frame's potential energy of the first n particles, -m omega^2 |r_perp|^2 / 2 each
// (Coriolis does no work, and the Euler force has no potential: with omega constant, kinetic +
// this + elastic energy is conserved), relative to the radius `reference_radius` (m).
double frame_potential_energy(const Particles& p, std::size_t n, const RotatingFrame& frame, double time,
                              double reference_radius);

}  // namespace trapdem
