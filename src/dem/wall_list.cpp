#include "dem/wall_list.hpp"

#include <omp.h>

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/thread_block.hpp"

namespace trapdem {

void build_wall_candidates(const Particles& p, std::size_t n, const std::vector<Wall>& walls, double skin,
                           WallList& out) {
  out.first.assign(n + 1, 0);
  std::vector<std::vector<std::uint32_t>> found(static_cast<std::size_t>(omp_get_max_threads()));
  std::size_t crowded = n;  // the first particle within reach of too many walls, n when none
  // As build_pairs: each thread lists the candidates of its block, then copies them into place;
  // the list is the same for any thread count. An error is thrown after the parallel region.
#pragma omp parallel
  {
    const int me = omp_get_thread_num();
    const auto [begin, end] = thread_block(n, me, omp_get_num_threads());
    std::vector<std::uint32_t>& mine = found[std::size_t(me)];
    mine.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t before = mine.size();
      for (std::uint32_t w = 0; w < walls.size(); ++w) {
        const WallProximity near = wall_proximity(walls[w], p.position[i]);
        if (near.distance < p.radius[i] + skin) mine.push_back(w);
      }
      out.first[i + 1] = static_cast<std::uint32_t>(mine.size() - before);
      if (out.first[i + 1] > kMaxWallCandidates) {
#pragma omp critical(trapdem_wall_candidates)
        crowded = std::min(crowded, i);
      }
    }
#pragma omp barrier
#pragma omp single
    {
      std::partial_sum(out.first.begin(), out.first.end(), out.first.begin());
      out.wall.resize(out.first[n]);
    }
    std::copy(mine.begin(), mine.end(), out.wall.begin() + out.first[begin]);
  }
  if (crowded < n)
    throw InputError(fmt::format("particle id {} is within reach of {} walls; at most {} are supported", p.id[crowded],
                                 out.first[crowded + 1] - out.first[crowded], kMaxWallCandidates));
  out.history.assign(out.wall.size(), ContactHistory{});
  out.force.assign(out.wall.size(), Vec3{});
}

}  // namespace trapdem
