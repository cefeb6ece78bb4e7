#include "dem/pair_list.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <numeric>

#include "dem/thread_block.hpp"

namespace trapdem {

std::uint32_t PairList::owner_of(std::size_t pair) const {
  auto it = std::upper_bound(first.begin(), first.end(), static_cast<std::uint32_t>(pair));
  return static_cast<std::uint32_t>(it - first.begin() - 1);
}

void build_pairs(const Particles& p, const CellSort& cells, const Domain& domain, double skin, PairList& out) {
  const std::size_t n = p.size();
  const bool periodic = domain.any_periodic();
  // In cell order (the engine re-orders the particles at every rebuild by default) a cell of lower
  // index holds lower particle indices only: a half list's partners j > i are then in the
  // particle's own cell and the higher cells of its stencil, half the cells to search.
  const bool in_cell_order = std::is_sorted(cells.cell_of.begin(), cells.cell_of.end());
  out.first.assign(n + 1, 0);
  std::vector<std::vector<std::uint32_t>> found(static_cast<std::size_t>(omp_get_max_threads()));
  // One pass: each thread lists the partners of a contiguous block of particles, then copies them
  // into place; the list is the same for any thread count.
#pragma omp parallel
  {
    const int me = omp_get_thread_num();
    const auto [begin, end] = thread_block(n, me, omp_get_num_threads());
    std::vector<std::uint32_t>& mine = found[std::size_t(me)];
    std::size_t used = 0;  // mine's first `used` entries are the block's partners
    std::array<std::uint32_t, 27> stencil;
    int stencil_size = 0;
    std::size_t stencil_particles = 0;  // how many particles the stencil's cells hold
    std::uint32_t stencil_of = ~0u;
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t cell = cells.cell_of[i];
      if (cell != stencil_of) {
        stencil_size = cells.grid.neighbours(cell, stencil);
        if (in_cell_order)
          stencil_size = int(std::remove_if(stencil.begin(), stencil.begin() + stencil_size,
                                            [cell](std::uint32_t c) { return c < cell; }) -
                             stencil.begin());
        stencil_particles = 0;
        for (int c = 0; c < stencil_size; ++c)
          stencil_particles += cells.cell_start[stencil[c] + 1] - cells.cell_start[stencil[c]];
        stencil_of = cell;
      }
      // Every candidate is written and kept only when within reach: no branch on the distance,
      // which keeps a minority of the candidates, at random (a mispredicted branch each kept pair).
      if (mine.size() < used + stencil_particles) mine.resize(2 * (used + stencil_particles));
      const std::size_t before = used;
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i] + skin;
      for (int c = 0; c < stencil_size; ++c) {
        for (std::uint32_t s = cells.cell_start[stencil[c]]; s < cells.cell_start[stencil[c] + 1]; ++s) {
          const std::uint32_t j = cells.order[s];
          Vec3 d = xi - p.position[j];
          if (periodic) d = domain.minimum_image(d);
          const double reach = ri + p.radius[j];
          mine[used] = j;
          used += (j > i) & (norm2(d) < reach * reach);
        }
      }
      std::sort(mine.begin() + std::ptrdiff_t(before), mine.begin() + std::ptrdiff_t(used));
      out.first[i + 1] = static_cast<std::uint32_t>(used - before);
    }
#pragma omp barrier
#pragma omp single
    {
      std::partial_sum(out.first.begin(), out.first.end(), out.first.begin());
      out.partner.resize(out.first[n]);
    }
    std::copy(mine.begin(), mine.begin() + std::ptrdiff_t(used), out.partner.begin() + out.first[begin]);
  }
  out.history.clear();
}

void keep_pairs_computed_here(PairList& list, std::size_t owned, const std::vector<std::int64_t>& id) {
  const std::size_t n = list.first.size() - 1;
  std::uint32_t kept = 0;
  std::uint32_t from = list.first[0];
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t to = list.first[i + 1];
    if (i < owned) {
      for (std::uint32_t k = from; k < to; ++k) {
        const std::uint32_t j = list.partner[k];
        if (j < owned || id[i] < id[j]) list.partner[kept++] = j;
      }
    }
    from = to;
    list.first[i + 1] = kept;
  }
  list.partner.resize(kept);
}

}  // namespace trapdem
