#include "dem/integrator.hpp"

#include <algorithm>
#include <limits>

namespace trapdem {

EscapeBounds escape_bounds(const Domain& domain) {
  EscapeBounds b{domain.lower, domain.upper};
  for (int a = 0; a < 3; ++a) {
    if (domain.periodic[a]) {
      b.lo[a] = -std::numeric_limits<double>::infinity();
      b.hi[a] = std::numeric_limits<double>::infinity();
    }
  }
  return b;
}

DriftReport first_half_kick_and_drift(Particles& p, std::size_t n, const Vec3* position_at_build, const Vec3& gravity, double dt,
                                      const Domain& domain, bool rotate) {
  const double half = 0.5 * dt;
  const Vec3 g = gravity;
  const EscapeBounds bounds = escape_bounds(domain);
  Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
  Vec3* w = p.angular_velocity.data();
  const Vec3* f = p.force.data();
  const Vec3* t = p.torque.data();
  const double* inv_m = p.inv_mass.data();
  const double* inv_i = p.inv_inertia.data();
  const bool track = position_at_build != nullptr;
  const Vec3* x0 = position_at_build;
  // Whether any particle left is a flag here (a reduction the loop vectorises with); which one,
  // only when one did.
  double max_d2 = 0.0;
  int outside = 0;
#pragma omp parallel for simd schedule(static) reduction(max : max_d2) reduction(| : outside)
  for (std::size_t i = 0; i < n; ++i) {
    kick_and_drift(x[i], v[i], w[i], f[i], t[i], inv_m[i], inv_i[i], g, half, dt, rotate);
    if (track) max_d2 = std::max(max_d2, norm2(x[i] - x0[i]));
    outside |= bounds.inside(x[i]) ? 0 : 1;
  }
  DriftReport report;
  report.max_displacement2 = max_d2;
  for (std::size_t i = 0; outside && i < n; ++i) {
    if (!bounds.inside(x[i])) {
      report.escaped = std::int64_t(i);
      break;
    }
  }
  return report;
}

std::int64_t SweepDrift::operator()(std::size_t begin, std::size_t end) const {
  Vec3* __restrict xs = x;  // local copies: the loop vectorises as first_half_kick_and_drift's does
  Vec3* __restrict vs = v;
  Vec3* __restrict ws = w;
  Vec3* __restrict fs = f;
  Vec3* __restrict ts = t;
  const double* __restrict inv_ms = inv_m;
  const double* __restrict inv_is = inv_i;
  const Vec3 gravity = g;
  const EscapeBounds box = bounds;
  int outside = 0;
#pragma omp simd reduction(| : outside)
  for (std::size_t i = begin; i < end; ++i) {
    kick_and_drift(xs[i], vs[i], ws[i], fs[i], ts[i], inv_ms[i], inv_is[i], gravity, half, dt, rotate);
    fs[i] = Vec3{};
    ts[i] = Vec3{};
    outside |= box.inside(xs[i]) ? 0 : 1;
  }
  for (std::size_t i = begin; outside && i < end; ++i)
    if (!box.inside(xs[i])) return std::int64_t(i);
  return -1;
}

int kick_and_forecast(const SecondHalfKick& kick, const DriftForecast* forecast, std::size_t begin, std::size_t end,
                      double& max_displacement2) {
  int bad = 0;
  for (std::size_t p = begin; p < end; ++p) bad |= kick(p);
  if (forecast) {
    const DriftForecast next = *forecast;
    double d2 = max_displacement2;
#pragma omp simd reduction(max : d2)
    for (std::size_t p = begin; p < end; ++p) d2 = std::max(d2, next(p));
    max_displacement2 = d2;
  }
  return bad;
}

void move_walls(std::vector<Wall>& walls, double time, double dt) {
  for (Wall& wall : walls) {
    wall.current_velocity = wall.velocity ? wall.velocity(time + 0.5 * dt) : Vec3{};
    wall.origin += dt * wall.current_velocity;
    wall.displacement += dt * wall.current_velocity;
  }
}

}  // namespace trapdem
