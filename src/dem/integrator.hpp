#pragma once
// Velocity Verlet as LAMMPS's nve/sphere: the first half kick and drift of every particle (with
// the escape check and the displacement since the last list build), the walls' prescribed
// motion, and the second half kick of one particle whose force is complete (the contact sweep
// gives it as soon as it is).
#include <cstdint>
#include <vector>

#include "dem/domain.hpp"
#include "dem/particles.hpp"
#include "dem/vec3.hpp"
#include "dem/wall.hpp"

namespace trapdem {

// The particles' displacements since the last list build, as the rebuild criterion needs them
// (Simulation::lists_outdated): the largest length and the box bounding the displacement vectors.
struct DisplacementsSinceBuild {
  double max_length2 = 0.0;  // m^2, the largest squared displacement
  Vec3 lowest{}, highest{};  // m, per axis the smallest and largest displacement component
  // m, a bound on |d_i - d_j| over every two particles: the smaller of twice the largest length and
  // the diagonal of the box around the displacement vectors. The box wins when the particles that
  // move most move alike (a rain of beads over a bed at rest, a block over a lowered trapdoor):
  // then two of them do not approach each other, and one of them and one at rest approach by its
  // own displacement, not by twice the largest.
  double pair_bound() const;
  // m, a bound on |d_i - D| over every particle, for a wall translated by D since the build (walls
  // only translate: the distance from x + d to the wall moved by D is the distance from x + d - D
  // to the wall, within |d - D| of the distance from x): the smaller of the largest length + |D|
  // and the distance from D to the box's farthest corner. The box wins when the particles that move
  // most move with the wall (a block riding a lowered trapdoor): the door and the block then do not
  // approach, and the door and a particle at rest approach by the door's own travel.
  double wall_bound(const Vec3& wall_displacement) const;
};

struct DriftReport {
  DisplacementsSinceBuild displacements;  // of the owned particles; zero when not tracked
  std::int64_t escaped = -1;              // the first particle outside the domain's bounded axes, or -1
};

// v += dt/2 (F/m + g), x += dt v, w += dt/2 T/I (w unchanged when `rotate` is false), for the
// first n particles (the owned ones: a rank's ghosts move with their owners).
// `position_at_build`: the positions at the last list build, or null when they are not tracked.
DriftReport first_half_kick_and_drift(Particles& p, std::size_t n, const Vec3* position_at_build, const Vec3& gravity, double dt,
                                      const Domain& domain, bool rotate);

// The bounds of the escape check: the domain's, none (infinite) on periodic axes.
void escape_bounds(const Domain& domain, Vec3& lo, Vec3& hi);

// Each wall moves by its prescribed velocity at the middle of the step [time, time + dt].
void move_walls(std::vector<Wall>& walls, double time, double dt);

// The second half kick for one particle whose force is complete: v += dt/2 (F/m + g),
// w = spin_retention (w + dt/2 T/I). spin_retention is 1 (the product then exact) unless the
// particle law's rolling model damps spin once per step (contact/rolling_angular_damping.hpp).
// Returns 1 when the result is not finite.
struct SecondHalfKick {
  Vec3* __restrict v;
  Vec3* __restrict w;
  const Vec3* __restrict f;
  const Vec3* __restrict t;
  const double* __restrict inv_m;
  const double* __restrict inv_i;
  Vec3 g;
  double half;
  bool rotate;
  double spin_retention;
  int operator()(std::size_t p) const {
    v[p] += half * (f[p] * inv_m[p] + g);
    if (rotate) w[p] = (w[p] + (half * inv_i[p]) * t[p]) * spin_retention;
    return is_finite(v[p]) && is_finite(w[p]) ? 0 : 1;
  }
};

}  // namespace trapdem
