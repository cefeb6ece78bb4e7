#include "io/particle_checks.hpp"

#include <cmath>
#include <unordered_set>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

[[noreturn]] void damaged(const std::string& where, std::size_t row, std::int64_t id, const std::string& what) {
  throw FileError(fmt::format("{}: row {} (particle id {}): {} (the file is damaged or was not written by trapdem)",
                              where, row, id, what));
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
                           const std::vector<double>& values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!(values[k] > 0.0) || !std::isfinite(values[k]))
      damaged(where, k, id[k], fmt::format("{} {}: expected a positive finite number", column, values[k]));
}

void check_finite_column(const std::string& where, const char* column, const std::vector<std::int64_t>& id,
                         const std::vector<Vec3>& values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!is_finite(values[k])) damaged(where, k, id[k], fmt::format("{} {}: expected finite numbers", column, text(values[k])));
}

}  // namespace trapdem
