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

void move_walls(std::vector<Wall>& walls, double time, double dt) {
  for (Wall& wall : walls) {
    wall.current_velocity = wall.velocity ? wall.velocity(time + 0.5 * dt) : Vec3{};
    wall.origin += dt * wall.current_velocity;
    wall.displacement += dt * wall.current_velocity;
  }
}

}  // namespace trapdem
