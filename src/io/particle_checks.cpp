#include "io/particle_checks.hpp"

#include <cmath>
#include <unordered_set>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

[[noreturn]] void damaged(const std::string& where, std::size_t row, std::int64_t id, const std::string& what,
                          const char* kind = "particle") {
  throw FileError(fmt::format("{}: row {} ({} id {}): {} (the file is damaged or was not written by trapdem)", where,
                              row, kind, id, what));
}

std::string text(const Vec3& v) { return fmt::format("({}, {}, {})", v.x, v.y, v.z); }

}  // namespace

void check_particle_rows(const std::string& where, const std::vector<std::int64_t>& id, const std::vector<Vec3>& position,
                         const std::vector<double>& radius, const std::vector<Vec3>& velocity,
                         const std::vector<Vec3>& angular_velocity, bool distinct_ids) {
  std::unordered_set<std::int64_t> seen;
  seen.reserve(id.size());
  for (std::size_t k = 0; k < id.size(); ++k) {
    if (id[k] < 0) damaged(where, k, id[k], "expected a particle id >= 0");
    if (distinct_ids && !seen.insert(id[k]).second) damaged(where, k, id[k], "the id appears twice: expected each particle once");
    if (!is_finite(position[k])) damaged(where, k, id[k], fmt::format("position {} m: expected finite numbers", text(position[k])));
    if (!(radius[k] > 0.0) || !std::isfinite(radius[k]))
      damaged(where, k, id[k], fmt::format("radius {} m: expected a positive finite number", radius[k]));
    if (!velocity.empty() && !(norm(velocity[k]) <= kMaxReadSpeed))
      damaged(where, k, id[k], fmt::format("velocity {} m/s: expected finite numbers, a speed of at most {:g} m/s",
                                           text(velocity[k]), kMaxReadSpeed));
    if (!angular_velocity.empty() && !(norm(angular_velocity[k]) * radius[k] <= kMaxReadSpeed))
      damaged(where, k, id[k], fmt::format("angular velocity {} rad/s: expected finite numbers, a surface speed of at "
                                           "most {:g} m/s", text(angular_velocity[k]), kMaxReadSpeed));
  }
}

void check_positive_column(const std::string& where, const char* column, const std::vector<std::int64_t>& id,
                           const std::vector<double>& values, const char* row) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!(values[k] > 0.0) || !std::isfinite(values[k]))
      damaged(where, k, id[k], fmt::format("{} {}: expected a positive finite number", column, values[k]), row);
}

void check_finite_column(const std::string& where, const char* column, const std::vector<std::int64_t>& id,
                         const std::vector<Vec3>& values, const char* row) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!is_finite(values[k]))
      damaged(where, k, id[k], fmt::format("{} {}: expected finite numbers", column, text(values[k])), row);
}

void check_body_rows(const std::string& where, const std::vector<std::int64_t>& id, const std::vector<Vec3>& position,
                     const std::vector<Vec3>& velocity, const std::vector<Quaternion>& orientation) {
  std::unordered_set<std::int64_t> seen;
  seen.reserve(id.size());
  for (std::size_t k = 0; k < id.size(); ++k) {
    if (id[k] < 0) damaged(where, k, id[k], "expected a body id >= 0", "body");
    if (!seen.insert(id[k]).second) damaged(where, k, id[k], "the id appears twice: expected each body once", "body");
    if (!is_finite(position[k]))
      damaged(where, k, id[k], fmt::format("centre of mass {} m: expected finite numbers", text(position[k])), "body");
    if (!(norm(velocity[k]) <= kMaxReadSpeed))
      damaged(where, k, id[k], fmt::format("velocity {} m/s: expected finite numbers, a speed of at most {:g} m/s",
                                           text(velocity[k]), kMaxReadSpeed), "body");
    const Quaternion& q = orientation[k];
    const double length = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!(std::fabs(length - 1.0) <= 1e-6))
      damaged(where, k, id[k], fmt::format("orientation ({}, {}, {}, {}) (w, x, y, z): expected a unit quaternion",
                                           q.w, q.x, q.y, q.z), "body");
  }
}

void check_body_members(const std::string& where, const std::vector<std::int64_t>& body_id,
                        const std::vector<std::uint32_t>& first_member, const std::vector<std::int64_t>& member_id,
                        const std::vector<std::int64_t>& particle_id) {
  const std::size_t bodies = body_id.size();
  if (first_member.size() != bodies + 1 || first_member.front() != 0 || first_member.back() != member_id.size())
    throw FileError(fmt::format("{}: first_member has {} entries from {} to {}: expected {} (one per body and one "
                                "more) from 0 to {}, the member count (the file is damaged)",
                                where, first_member.size(), first_member.empty() ? 0 : first_member.front(),
                                first_member.empty() ? 0 : first_member.back(), bodies + 1, member_id.size()));
  for (std::size_t b = 0; b < bodies; ++b)
    if (!(first_member[b + 1] > first_member[b]))
      damaged(where, b, body_id[b],
              fmt::format("first_member {} then {}: expected at least one member per body", first_member[b],
                          first_member[b + 1]),
              "body");
  std::unordered_set<std::int64_t> particles(particle_id.begin(), particle_id.end());
  std::unordered_set<std::int64_t> members;
  members.reserve(member_id.size());
  for (std::size_t b = 0; b < bodies; ++b)
    for (std::uint32_t m = first_member[b]; m < first_member[b + 1]; ++m) {
      if (!particles.count(member_id[m]))
        damaged(where, b, body_id[b], fmt::format("its member {} is not among the particles", member_id[m]), "body");
      if (!members.insert(member_id[m]).second)
        damaged(where, b, body_id[b], fmt::format("its member {} is a member twice: expected each sphere in one body",
                                                  member_id[m]), "body");
    }
  if (members.size() != particles.size())
    throw FileError(fmt::format("{}: {} of the {} particles are members of bodies: in a run with bodies every particle "
                                "is a member of one (the file is damaged)", where, members.size(), particles.size()));
}

}  // namespace trapdem
