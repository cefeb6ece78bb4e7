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

// The first half kick and drift of one particle: v += dt/2 (F/m + g), x += dt v, w += dt/2 T/I
// (w unchanged when `rotate` is false). Written once for the pass over all particles, the sweep
// that does it just ahead of each particle's first use and the forecast of the next step's
// displacement (DriftForecast), so that all three give the same bits.
[[gnu::always_inline]] inline void kick_and_drift(Vec3& x, Vec3& v, Vec3& w, const Vec3& f, const Vec3& t, double inv_m,
                                                  double inv_i, const Vec3& g, double half, double dt, bool rotate) {
  v += half * (f * inv_m + g);
  x += dt * v;
  if (rotate) w += (half * inv_i) * t;
}

// The box a particle must stay in: the domain's bounds on bounded axes, none on periodic ones.
struct EscapeBounds {
  Vec3 lo, hi;  // m
  bool inside(const Vec3& x) const {  // false for NaN too
    return x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z;
  }
};
EscapeBounds escape_bounds(const Domain& domain);

struct DriftReport {
  double max_displacement2 = 0.0;  // m^2, largest squared displacement since the list build
  std::int64_t escaped = -1;       // the first particle outside the domain's bounded axes, or -1
};

// v += dt/2 (F/m + g), x += dt v, w += dt/2 T/I (w unchanged when `rotate` is false), for the
// first n particles (the owned ones: a rank's ghosts move with their owners).
// `position_at_build`: the positions at the last list build, or null when they are not tracked.
DriftReport first_half_kick_and_drift(Particles& p, std::size_t n, const Vec3* position_at_build, const Vec3& gravity, double dt,
                                      const Domain& domain, bool rotate);

// Each wall moves by its prescribed velocity at the middle of the step [time, time + dt].
void move_walls(std::vector<Wall>& walls, double time, double dt);

// The second half kick for one particle whose force is complete: v += dt/2 (F/m + g),
// w += dt/2 T/I. Returns 1 when the result is not finite.
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
  int operator()(std::size_t p) const {
    v[p] += half * (f[p] * inv_m[p] + g);
    if (rotate) w[p] += (half * inv_i[p]) * t[p];
    return is_finite(v[p]) && is_finite(w[p]) ? 0 : 1;
  }
};

// The first half kick and drift of particles inside the contact sweep (Simulation::contacts), a
// stretch at a time just before the sweep first reads them; their forces and torques, read by
// the kick, are then cleared for the sweep to sum into.
struct SweepDrift {
  Vec3* __restrict x;
  Vec3* __restrict v;
  Vec3* __restrict w;
  Vec3* __restrict f;
  Vec3* __restrict t;
  const double* __restrict inv_m;
  const double* __restrict inv_i;
  Vec3 g;
  double half, dt;
  bool rotate;
  EscapeBounds bounds;
  // Particles [begin, end); returns the first that left the domain's bounded axes, or -1.
  std::int64_t operator()(std::size_t begin, std::size_t end) const;
};

// The squared displacement since the last list build (m^2) that the next step's first half kick
// and drift will give particle p, once p's second half kick is done: its force, velocity and
// position are then the ones that drift reads, and nothing changes them before it unless the
// state is changed between steps (the engine then drops the forecast). The next step decides on
// a list rebuild from the largest of these before any particle moves, and may then drift each
// particle inside the sweep (SweepDrift) instead of in a pass of its own.
struct DriftForecast {
  const Vec3* __restrict x;
  const Vec3* __restrict v;
  const Vec3* __restrict f;
  const double* __restrict inv_m;
  const Vec3* __restrict position_at_build;
  Vec3 g;  // the next step's first half kick's gravity (the second half kick's: both at the same time)
  double half, dt;
  double operator()(std::size_t p) const {
    Vec3 x_next = x[p], v_next = v[p], unused{};
    kick_and_drift(x_next, v_next, unused, f[p], Vec3{}, inv_m[p], 0.0, g, half, dt, false);
    return norm2(x_next - position_at_build[p]);
  }
};

// The second half kick of particles [begin, end) and, with a forecast, the largest forecast
// displacement among them raised into max_displacement2 (m^2). Returns 1 when a kicked state is
// not finite.
int kick_and_forecast(const SecondHalfKick& kick, const DriftForecast* forecast, std::size_t begin, std::size_t end,
                      double& max_displacement2);

}  // namespace trapdem
