#include "dem/rigid/rigid_bodies.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/pair_list.hpp"
#include "dem/permutation.hpp"

namespace trapdem {

Vec3 RigidBodies::angular_velocity(std::size_t b) const {
  const Vec3& inertia = principal_inertia[b];
  const Vec3 momentum_body = rotate_inverse(orientation[b], angular_momentum[b]);
  return rotate(orientation[b], Vec3{momentum_body.x / inertia.x, momentum_body.y / inertia.y, momentum_body.z / inertia.z});
}

std::size_t RigidBodies::body_of_member(std::size_t member) const {
  return std::size_t(std::upper_bound(first_member.begin(), first_member.end(), std::uint32_t(member)) -
                     first_member.begin()) - 1;
}

void RigidBodies::locate_members(const std::vector<std::int64_t>& particle_id) {
  // The particles' ids sorted once, each member found by binary search: O((N + M) log N), run at
  // a list build only (the particles are re-ordered nowhere else).
  std::vector<std::uint32_t> by_id(particle_id.size());
  std::iota(by_id.begin(), by_id.end(), 0u);
  std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return particle_id[a] < particle_id[b]; });
  member_particle.resize(member_count());
  body_of_particle.assign(particle_id.size(), kNoBody);
  for (std::size_t b = 0; b < size(); ++b)
    for (std::uint32_t m = first_member[b]; m < first_member[b + 1]; ++m) {
      const auto it = std::lower_bound(by_id.begin(), by_id.end(), member_id[m],
                                       [&](std::uint32_t i, std::int64_t want) { return particle_id[i] < want; });
      if (it == by_id.end() || particle_id[*it] != member_id[m])
        throw SimulationError(fmt::format("body {}: its member sphere {} is not among the particles", id[b], member_id[m]));
      member_particle[m] = *it;
      body_of_particle[*it] = std::uint32_t(b);
    }
  for (std::size_t i = 0; i < particle_id.size(); ++i)
    if (body_of_particle[i] == kNoBody)
      throw SimulationError(fmt::format("particle {} belongs to no body; in a run with clumps every sphere is a "
                                        "member of one (a lone sphere: a body of one member)", particle_id[i]));
}

void RigidBodies::follow_particle_permutation(const std::vector<std::uint32_t>& order) {
  const std::size_t n_particles = order.size();
  std::vector<std::uint32_t> now_at(n_particles);
  for (std::size_t i = 0; i < n_particles; ++i) now_at[order[i]] = std::uint32_t(i);
  for (std::uint32_t& i : member_particle) i = now_at[i];

  // The bodies by their first member's place (each particle is one body's: the keys are distinct).
  const std::size_t n = size();
  std::vector<std::uint32_t> key(n);
  bool sorted = true;
  for (std::size_t b = 0; b < n; ++b) {
    std::uint32_t first = ~0u;
    for (std::uint32_t m = first_member[b]; m < first_member[b + 1]; ++m) first = std::min(first, member_particle[m]);
    key[b] = first;
    sorted = sorted && (b == 0 || key[b - 1] < first);
  }
  if (!sorted) {
    std::vector<std::uint32_t> body_order(n);
    std::iota(body_order.begin(), body_order.end(), 0u);
    std::sort(body_order.begin(), body_order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    apply_permutation(id, body_order);
    apply_permutation(mass, body_order);
    apply_permutation(volume, body_order);
    apply_permutation(principal_inertia, body_order);
    apply_permutation(position, body_order);
    apply_permutation(velocity, body_order);
    apply_permutation(orientation, body_order);
    apply_permutation(angular_momentum, body_order);
    apply_permutation(force, body_order);
    apply_permutation(torque, body_order);
    if (inverse_inertia.size() == n) apply_permutation(inverse_inertia, body_order);
    // The members' arrays, body by body in the new order.
    const bool with_arms = arm.size() == member_count();
    std::vector<std::uint32_t> new_first(n + 1, 0);
    std::vector<std::int64_t> new_member_id;
    std::vector<Vec3> new_offset, new_arm;
    std::vector<std::uint32_t> new_particle;
    new_member_id.reserve(member_count());
    new_offset.reserve(member_count());
    new_particle.reserve(member_count());
    if (with_arms) new_arm.reserve(member_count());
    for (std::size_t b = 0; b < n; ++b) {
      const std::uint32_t was = body_order[b];
      for (std::uint32_t m = first_member[was]; m < first_member[was + 1]; ++m) {
        new_member_id.push_back(member_id[m]);
        new_offset.push_back(member_offset[m]);
        new_particle.push_back(member_particle[m]);
        if (with_arms) new_arm.push_back(arm[m]);
      }
      new_first[b + 1] = std::uint32_t(new_member_id.size());
    }
    first_member.swap(new_first);
    member_id.swap(new_member_id);
    member_offset.swap(new_offset);
    member_particle.swap(new_particle);
    if (with_arms) arm.swap(new_arm);
  }
  body_of_particle.assign(n_particles, kNoBody);
  for (std::size_t b = 0; b < n; ++b)
    for (std::uint32_t m = first_member[b]; m < first_member[b + 1]; ++m) body_of_particle[member_particle[m]] = std::uint32_t(b);
}

void RigidBodies::clear() { *this = RigidBodies{}; }

std::size_t add_rigid_body(RigidBodies& bodies, Particles& particles, std::int64_t body_id,
                           std::int64_t first_member_id, const ClumpTemplate& shape, double density,
                           const Vec3& position, const Quaternion& orientation, const Vec3& velocity,
                           const Vec3& angular_velocity) {
  if (!(density > 0.0) || !(shape.volume > 0.0) || shape.members.empty())
    throw InputError(fmt::format("body {}: density ({} kg/m3) and the shape's volume ({} m3) must be positive", body_id,
                                 density, shape.volume));
  const double mass = density * shape.volume;
  const Vec3 inertia = density * shape.principal_inertia;
  const Quaternion q = normalised(orientation);
  bodies.id.push_back(body_id);
  bodies.mass.push_back(mass);
  bodies.volume.push_back(shape.volume);
  bodies.principal_inertia.push_back(inertia);
  bodies.position.push_back(position);
  bodies.velocity.push_back(velocity);
  bodies.orientation.push_back(q);
  // L = R I R^T omega: the body-frame angular velocity times the principal moments, turned back.
  const Vec3 w_body = rotate_inverse(q, angular_velocity);
  bodies.angular_momentum.push_back(rotate(q, Vec3{inertia.x * w_body.x, inertia.y * w_body.y, inertia.z * w_body.z}));
  bodies.force.push_back({});
  bodies.torque.push_back({});
  // The members' mass is the body's (the contact's effective mass) and their inertia the body's
  // mean principal moment (rigid_bodies.hpp).
  const double mean_inverse_inertia = 3.0 / (inertia.x + inertia.y + inertia.z);
  for (std::size_t k = 0; k < shape.members.size(); ++k) {
    const ClumpMember& member = shape.members[k];
    const Vec3 arm = rotate(q, member.centre);
    const std::size_t i = particles.add(first_member_id + std::int64_t(k), position + arm, member.radius, density,
                                        velocity + cross(angular_velocity, arm), angular_velocity);
    particles.mass[i] = mass;
    particles.inv_mass[i] = 1.0 / mass;
    particles.inv_inertia[i] = mean_inverse_inertia;
    bodies.member_id.push_back(first_member_id + std::int64_t(k));
    bodies.member_offset.push_back(member.centre);
    // Appended: the derived arrays stay current without a search (a pour adds bodies between steps).
    bodies.member_particle.push_back(std::uint32_t(i));
    bodies.body_of_particle.resize(particles.size(), kNoBody);
    bodies.body_of_particle[i] = std::uint32_t(bodies.size() - 1);
  }
  bodies.first_member.push_back(std::uint32_t(bodies.member_id.size()));
  return bodies.size() - 1;
}

double contact_time_scale_mass(double mass, const Vec3& inertia, double reach) {
  const double least = std::min({inertia.x, inertia.y, inertia.z});
  return std::min(mass, least / (reach * reach));
}

BodyContactScale body_contact_scale(const RigidBodies& bodies, const Particles& particles, std::size_t b) {
  double reach = 0.0, smallest_radius = std::numeric_limits<double>::infinity();
  for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
    const double r = particles.radius[bodies.member_particle[m]];
    reach = std::max(reach, norm(bodies.member_offset[m]) + r);
    smallest_radius = std::min(smallest_radius, r);
  }
  return {contact_time_scale_mass(bodies.mass[b], bodies.principal_inertia[b], reach), smallest_radius};
}

void exclude_pairs_within_bodies(PairList& pairs, const std::vector<std::uint32_t>& body_of_particle) {
  // In place: each owner's kept partners move down; first[] renumbered as we go.
  std::uint32_t kept = 0;
  const std::size_t n = pairs.first.empty() ? 0 : pairs.first.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t begin = pairs.first[i], end = pairs.first[i + 1];
    pairs.first[i] = kept;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t j = pairs.partner[k];
      if (body_of_particle[i] != kNoBody && body_of_particle[i] == body_of_particle[j]) continue;
      pairs.partner[kept++] = j;
    }
  }
  if (n > 0) pairs.first[n] = kept;
  pairs.partner.resize(kept);
}

}  // namespace trapdem
