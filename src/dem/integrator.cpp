#include "dem/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trapdem {

double DisplacementsSinceBuild::pair_bound() const {
  // |d_i - d_j| <= |d_i| + |d_j| <= 2 max |d|; and d_i, d_j both lie in the box, so their
  // difference is at most its diagonal. An empty or untracked set has highest < lowest: no extent.
  double diagonal2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double extent = std::max(0.0, highest[a] - lowest[a]);
    diagonal2 += extent * extent;
  }
  return std::min(2.0 * std::sqrt(max_length2), std::sqrt(diagonal2));
}

double DisplacementsSinceBuild::wall_bound(const Vec3& wall_displacement) const {
  // |d - D| is convex in d, so over the box its largest value is at a corner: per axis the
  // farther of the two faces. An empty or untracked set (lowest = highest = 0) gives |D|.
  double farthest2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double to_face = std::max(std::fabs(highest[a] - wall_displacement[a]), std::fabs(lowest[a] - wall_displacement[a]));
    farthest2 += to_face * to_face;
  }
  return std::min(std::sqrt(max_length2) + norm(wall_displacement), std::sqrt(farthest2));
}

void escape_bounds(const Domain& domain, Vec3& lo, Vec3& hi) {
  lo = domain.lower;
  hi = domain.upper;
  for (int a = 0; a < 3; ++a) {
    if (domain.periodic[a]) {
      lo[a] = -std::numeric_limits<double>::infinity();
      hi[a] = std::numeric_limits<double>::infinity();
    }
  }
}

DriftReport first_half_kick_and_drift(Particles& p, std::size_t n, const Vec3* position_at_build, const Vec3& gravity, double dt,
                                      const Domain& domain, bool rotate) {
  const double half = 0.5 * dt;
  const Vec3 g = gravity;
  Vec3 lo, hi;
  escape_bounds(domain, lo, hi);
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
  // only when one did. The displacements' box as six scalars: OpenMP reduces scalars.
  double max_d2 = 0.0;
  constexpr double kHuge = std::numeric_limits<double>::infinity();
  double lo_x = kHuge, lo_y = kHuge, lo_z = kHuge, hi_x = -kHuge, hi_y = -kHuge, hi_z = -kHuge;
  int outside = 0;
#pragma omp parallel for simd schedule(static) reduction(max : max_d2, hi_x, hi_y, hi_z) \
    reduction(min : lo_x, lo_y, lo_z) reduction(| : outside)
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += half * (f[i] * inv_m[i] + g);
    x[i] += dt * v[i];
    if (rotate) w[i] += (half * inv_i[i]) * t[i];
    if (track) {
      const Vec3 d = x[i] - x0[i];
      max_d2 = std::max(max_d2, norm2(d));
      lo_x = std::min(lo_x, d.x);
      lo_y = std::min(lo_y, d.y);
      lo_z = std::min(lo_z, d.z);
      hi_x = std::max(hi_x, d.x);
      hi_y = std::max(hi_y, d.y);
      hi_z = std::max(hi_z, d.z);
    }
    const bool inside = x[i].x >= lo.x && x[i].x <= hi.x && x[i].y >= lo.y && x[i].y <= hi.y && x[i].z >= lo.z &&
                        x[i].z <= hi.z;  // false for NaN too
    outside |= inside ? 0 : 1;
  }
  DriftReport report;
  if (track && n > 0) report.displacements = {max_d2, {lo_x, lo_y, lo_z}, {hi_x, hi_y, hi_z}};
  for (std::size_t i = 0; outside && i < n; ++i) {
    const bool inside = x[i].x >= lo.x && x[i].x <= hi.x && x[i].y >= lo.y && x[i].y <= hi.y && x[i].z >= lo.z &&
                        x[i].z <= hi.z;
    if (!inside) {
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
