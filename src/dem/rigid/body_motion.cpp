#include "dem/rigid/body_motion.hpp"

#include "dem/rigid/free_rotation.hpp"

namespace trapdem {

void place_members(const RigidBodies& bodies, Particles& particles, bool positions) {
  const std::size_t n = bodies.size();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n; ++b) {
    const Vec3 w = bodies.angular_velocity(b);
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      const std::uint32_t i = bodies.member_particle[m];
      const Vec3 arm = bodies.member_arm(b, m);
      if (positions) particles.position[i] = bodies.position[b] + arm;
      particles.velocity[i] = bodies.velocity[b] + cross(w, arm);
      particles.angular_velocity[i] = w;
    }
  }
}

void bodies_first_half_kick_and_drift(RigidBodies& bodies, Particles& particles, const BodyKick& kick) {
  const std::size_t n = bodies.size();
  const double h = kick.half, dt = 2.0 * kick.half;
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n; ++b) {
    Vec3& v = bodies.velocity[b];
    if (kick.frame) v = kick.frame->coriolis_turn(v) + h * kick.frame->acceleration(bodies.position[b]);
    v += h * (bodies.force[b] / bodies.mass[b] + kick.gravity);
    bodies.position[b] += dt * v;
    if (!kick.rotate) continue;
    Vec3& L = bodies.angular_momentum[b];
    L += h * bodies.torque[b];
    // The free rotation keeps L in the space frame; only the orientation changes (and L's
    // body-frame components, which are not stored).
    Vec3 momentum_body = rotate_inverse(bodies.orientation[b], L);
    rotate_freely(bodies.orientation[b], momentum_body, bodies.principal_inertia[b], dt);
  }
  place_members(bodies, particles, true);
}

void reduce_member_loads(RigidBodies& bodies, const Particles& particles) {
  const std::size_t n = bodies.size();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < n; ++b) {
    Vec3 f{}, t{};
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      const std::uint32_t i = bodies.member_particle[m];
      f += particles.force[i];
      t += cross(bodies.member_arm(b, m), particles.force[i]) + particles.torque[i];
    }
    bodies.force[b] = f;
    bodies.torque[b] = t;
  }
}

int bodies_second_half_kick(RigidBodies& bodies, Particles& particles, const BodyKick& kick) {
  const std::size_t n = bodies.size();
  const double h = kick.half;
  int any_bad = 0;
#pragma omp parallel for schedule(static) reduction(| : any_bad)
  for (std::size_t b = 0; b < n; ++b) {
    Vec3& v = bodies.velocity[b];
    v += h * (bodies.force[b] / bodies.mass[b] + kick.gravity);
    if (kick.frame) v = kick.frame->coriolis_turn(v + h * kick.frame->acceleration(bodies.position[b]));
    Vec3& L = bodies.angular_momentum[b];
    if (kick.rotate) L = (L + h * bodies.torque[b]) * kick.spin_retention;
    any_bad |= is_finite(v) && is_finite(L) ? 0 : 1;
  }
  place_members(bodies, particles, false);
  return any_bad;
}

}  // namespace trapdem
