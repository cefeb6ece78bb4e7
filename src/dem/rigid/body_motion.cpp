#include "dem/rigid/body_motion.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "dem/rigid/free_rotation.hpp"

namespace trapdem {

namespace {

// The rotation matrix of a unit quaternion, by rows: one matrix per body instead of a quaternion
// product per member.
struct Rotation {
  Vec3 row0, row1, row2;
  explicit Rotation(const Quaternion& q) {
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    row0 = {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)};
    row1 = {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)};
    row2 = {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)};
  }
  Vec3 operator()(const Vec3& v) const { return {dot(row0, v), dot(row1, v), dot(row2, v)}; }
  Vec3 transposed(const Vec3& v) const {  // the inverse rotation
    return row0 * v.x + row1 * v.y + row2 * v.z;
  }
};

// Body b's inverse inertia tensor in the space frame, J = R I^-1 R^T: J_ij = sum_k R_ik R_jk / I_k,
// the rows of R scaled by 1/I dotted with the rows. Its product with L is the angular velocity.
[[gnu::always_inline]] inline SymmetricMatrix3 space_inverse_inertia(const Vec3& inertia, const Rotation& r) {
  const Vec3 inverse{1.0 / inertia.x, 1.0 / inertia.y, 1.0 / inertia.z};
  const Vec3 a{r.row0.x * inverse.x, r.row0.y * inverse.y, r.row0.z * inverse.z};
  const Vec3 b{r.row1.x * inverse.x, r.row1.y * inverse.y, r.row1.z * inverse.z};
  const Vec3 c{r.row2.x * inverse.x, r.row2.y * inverse.y, r.row2.z * inverse.z};
  return {dot(a, r.row0), dot(b, r.row1), dot(c, r.row2), dot(a, r.row1), dot(a, r.row2), dot(b, r.row2)};
}

void size_workspaces(RigidBodies& bodies) {
  bodies.arm.resize(bodies.member_count());
  bodies.inverse_inertia.resize(bodies.size());
}

// Body b's force and torque about its centre of mass from its members': F = sum f_i,
// T = sum (a_i x f_i + t_i), with the arms of the last placement.
[[gnu::always_inline]] inline void reduce_body_loads(RigidBodies& bodies, const Particles& particles, std::size_t b) {
  Vec3 f{}, t{};
  for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
    const std::uint32_t i = bodies.member_particle[m];
    f += particles.force[i];
    t += cross(bodies.arm[m], particles.force[i]) + particles.torque[i];
  }
  bodies.force[b] = f;
  bodies.torque[b] = t;
}

}  // namespace

void place_members(RigidBodies& bodies, Particles& particles, bool positions) {
  size_workspaces(bodies);
  const std::size_t n = bodies.size();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n; ++b) {
    const Rotation r(bodies.orientation[b]);
    const SymmetricMatrix3 J = space_inverse_inertia(bodies.principal_inertia[b], r);
    bodies.inverse_inertia[b] = J;
    const Vec3 w = J * bodies.angular_momentum[b];
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      const std::uint32_t i = bodies.member_particle[m];
      const Vec3 arm = positions ? r(bodies.member_offset[m]) : bodies.arm[m];
      bodies.arm[m] = arm;
      if (positions) particles.position[i] = bodies.position[b] + arm;
      particles.velocity[i] = bodies.velocity[b] + cross(w, arm);
      particles.angular_velocity[i] = w;
    }
  }
}

DriftReport bodies_first_half_kick_and_drift(RigidBodies& bodies, Particles& particles, const BodyKick& kick,
                                             const Vec3* position_at_build, const Domain& domain) {
  size_workspaces(bodies);
  const std::size_t n = bodies.size();
  const double h = kick.half, dt = 2.0 * kick.half;
  Vec3 lo, hi;
  escape_bounds(domain, lo, hi);
  const bool track = position_at_build != nullptr;
  constexpr double kHuge = std::numeric_limits<double>::infinity();
  double max_d2 = 0.0, lo_x = kHuge, lo_y = kHuge, lo_z = kHuge, hi_x = -kHuge, hi_y = -kHuge, hi_z = -kHuge;
  int outside = 0;
  // The bodies in groups of kRotationLanes, whose free rotations run side by side.
  const std::size_t groups = (n + kRotationLanes - 1) / kRotationLanes;
#pragma omp parallel for schedule(static)
  for (std::size_t group = 0; group < groups; ++group) {
    const std::size_t first = group * kRotationLanes;
    const int count = int(std::min<std::size_t>(kRotationLanes, n - first));
    Vec3 momentum_body[kRotationLanes];
    for (int k = 0; k < count; ++k) {
      const std::size_t b = first + std::size_t(k);
      Vec3& v = bodies.velocity[b];
      if (kick.frame) v = kick.frame->coriolis_turn(v) + h * kick.frame->acceleration(bodies.position[b]);
      v += h * (bodies.force[b] / bodies.mass[b] + kick.gravity);
      bodies.position[b] += dt * v;
      if (!kick.rotate) continue;
      Vec3& L = bodies.angular_momentum[b];
      L += h * bodies.torque[b];
      // The free rotation keeps L in the space frame; only the orientation changes (and L's
      // body-frame components, which are not stored).
      momentum_body[k] = rotate_inverse(bodies.orientation[b], L);
    }
    if (kick.rotate)
      rotate_freely_lanes(&bodies.orientation[first], momentum_body, &bodies.principal_inertia[first], dt, count);
  }
  // The members placed, with the rebuild criterion's displacements and the escape check: a loop of
  // its own, so that the free rotations above (a long chain of dependent operations each) overlap
  // from one body to the next.
#pragma omp parallel for schedule(static) reduction(max : max_d2, hi_x, hi_y, hi_z) \
    reduction(min : lo_x, lo_y, lo_z) reduction(| : outside)
  for (std::size_t b = 0; b < n; ++b) {
    const Vec3& v = bodies.velocity[b];
    const Rotation r(bodies.orientation[b]);
    const SymmetricMatrix3 J = space_inverse_inertia(bodies.principal_inertia[b], r);
    bodies.inverse_inertia[b] = J;
    const Vec3 w = J * bodies.angular_momentum[b];
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      const std::uint32_t i = bodies.member_particle[m];
      const Vec3 arm = r(bodies.member_offset[m]);
      bodies.arm[m] = arm;
      const Vec3 x = bodies.position[b] + arm;
      particles.position[i] = x;
      particles.velocity[i] = v + cross(w, arm);
      particles.angular_velocity[i] = w;
      if (track) {
        const Vec3 d = x - position_at_build[i];
        max_d2 = std::max(max_d2, norm2(d));
        lo_x = std::min(lo_x, d.x);
        lo_y = std::min(lo_y, d.y);
        lo_z = std::min(lo_z, d.z);
        hi_x = std::max(hi_x, d.x);
        hi_y = std::max(hi_y, d.y);
        hi_z = std::max(hi_z, d.z);
      }
      const bool inside = x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z;
      outside |= inside ? 0 : 1;  // false for NaN too
    }
  }
  DriftReport report;
  if (track && n > 0) report.displacements = {max_d2, {lo_x, lo_y, lo_z}, {hi_x, hi_y, hi_z}};
  for (std::size_t i = 0; outside && i < particles.size(); ++i) {
    const Vec3& x = particles.position[i];
    if (!(x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z)) {
      report.escaped = std::int64_t(i);
      break;
    }
  }
  return report;
}

void reduce_member_loads(RigidBodies& bodies, const Particles& particles) {
  if (bodies.arm.size() != bodies.member_count())
    throw std::logic_error("reduce_member_loads: the members' arms are not current (place_members first)");
  const std::size_t n = bodies.size();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n; ++b) reduce_body_loads(bodies, particles, b);
}

int bodies_second_half_kick(RigidBodies& bodies, Particles& particles, const BodyKick& kick) {
  if (bodies.inverse_inertia.size() != bodies.size() || bodies.arm.size() != bodies.member_count())
    throw std::logic_error("bodies_second_half_kick: the workspaces are not current (place_members first)");
  const std::size_t n = bodies.size();
  const double h = kick.half;
  int any_bad = 0;
#pragma omp parallel for schedule(static) reduction(| : any_bad)
  for (std::size_t b = 0; b < n; ++b) {
    reduce_body_loads(bodies, particles, b);
    Vec3& v = bodies.velocity[b];
    v += h * (bodies.force[b] / bodies.mass[b] + kick.gravity);
    if (kick.frame) v = kick.frame->coriolis_turn(v + h * kick.frame->acceleration(bodies.position[b]));
    Vec3& L = bodies.angular_momentum[b];
    if (kick.rotate) L = (L + h * bodies.torque[b]) * kick.spin_retention;
    any_bad |= is_finite(v) && is_finite(L) ? 0 : 1;
    // The members' velocities and spins (their arms and J are this step's: the kick turns no body).
    const Vec3 w = bodies.inverse_inertia[b] * L;
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      const std::uint32_t i = bodies.member_particle[m];
      particles.velocity[i] = v + cross(w, bodies.arm[m]);
      particles.angular_velocity[i] = w;
    }
  }
  return any_bad;
}

}  // namespace trapdem
