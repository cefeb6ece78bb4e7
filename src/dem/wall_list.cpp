#include "dem/wall_list.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

void build_wall_candidates(const Particles& p, std::size_t n, const std::vector<Wall>& walls, double skin,
                           WallList& out) {
  out.first.assign(n + 1, 0);
  out.wall.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
      const WallProximity near = wall_proximity(walls[w], p.position[i]);
      if (near.distance < p.radius[i] + skin) out.wall.push_back(w);
    }
    out.first[i + 1] = static_cast<std::uint32_t>(out.wall.size());
    if (out.first[i + 1] - out.first[i] > kMaxWallCandidates)
      throw InputError(fmt::format("particle id {} is within reach of {} walls; at most {} are supported", p.id[i],
                                   out.first[i + 1] - out.first[i], kMaxWallCandidates));
  }
  out.history.assign(out.wall.size(), ContactHistory{});
  out.force.assign(out.wall.size(), Vec3{});
}

}  // namespace trapdem
