#include "dem/neighbor_list.hpp"

#include <omp.h>

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

std::uint32_t PairList::owner_of(std::size_t pair) const {
  auto it = std::upper_bound(first.begin(), first.end(), static_cast<std::uint32_t>(pair));
  return static_cast<std::uint32_t>(it - first.begin() - 1);
}

namespace {
ContactHistory flipped(ContactHistory h) {
  h.tangential_spring = -h.tangential_spring;
  h.rolling_spring = -h.rolling_spring;
  return h;
}
}  // namespace

void HistoryArchive::store_pairs(const PairList& list, const ContactSlots& slot, const ContactHistory* contacts,
                                 const std::vector<std::int64_t>& id) {
  pairs.clear();
  const std::size_t n = list.first.empty() ? 0 : list.first.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      if (slot[k] == kNoContact) continue;
      const ContactHistory& h = contacts[slot[k]];
      const std::int64_t a = id[i], b = id[list.partner[k]];
      pairs.push_back(a < b ? PairRecord{a, b, h} : PairRecord{b, a, flipped(h)});
    }
  }
}

namespace {
// The current index of each particle id: a table when the ids are dense (the usual 1..N, any
// order), else a search in the ids sorted.
class IndexOfId {
 public:
  static constexpr std::uint32_t kAbsent = ~0u;
  explicit IndexOfId(const std::vector<std::int64_t>& id) {
    if (id.empty()) return;
    const auto [lo, hi] = std::minmax_element(id.begin(), id.end());
    lowest_ = *lo;
    const auto range = static_cast<std::uint64_t>(*hi) - static_cast<std::uint64_t>(*lo);
    if (range < 4 * std::uint64_t(id.size()) + 64) {
      table_.assign(range + 1, kAbsent);
      for (std::size_t i = 0; i < id.size(); ++i) table_[std::size_t(id[i] - lowest_)] = std::uint32_t(i);
    } else {
      sorted_.reserve(id.size());
      for (std::size_t i = 0; i < id.size(); ++i) sorted_.push_back({id[i], std::uint32_t(i)});
      std::sort(sorted_.begin(), sorted_.end());
    }
  }
  std::uint32_t operator()(std::int64_t particle_id) const {
    if (!table_.empty()) {
      if (particle_id < lowest_) return kAbsent;
      const auto at = static_cast<std::uint64_t>(particle_id) - static_cast<std::uint64_t>(lowest_);
      return at < table_.size() ? table_[at] : kAbsent;
    }
    auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::pair<std::int64_t, std::uint32_t>{particle_id, 0});
    return it != sorted_.end() && it->first == particle_id ? it->second : kAbsent;
  }

 private:
  std::int64_t lowest_ = 0;
  std::vector<std::uint32_t> table_;
  std::vector<std::pair<std::int64_t, std::uint32_t>> sorted_;
};
}  // namespace

void HistoryArchive::store_walls(const WallList& list, const std::vector<std::int64_t>& id) {
  walls.clear();
  const std::size_t n = list.first.empty() ? 0 : list.first.size() - 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k)
      if (list.history[k].touching()) walls.push_back({id[i], list.wall[k], list.history[k]});
  std::sort(walls.begin(), walls.end(), [](const WallRecord& x, const WallRecord& y) {
    return x.particle != y.particle ? x.particle < y.particle : x.wall < y.wall;
  });
}

std::size_t HistoryArchive::restore_pairs(const PairList& list, const std::vector<std::int64_t>& id,
                                          ContactSlots& slot, ContactHistory* contacts) const {
  const std::size_t n = list.first.size() - 1;
  slot.assign(list.size(), kNoContact);
  if (pairs.empty()) return 0;
  // Each record's pair in current indices, grouped by its owner (the lower index) with a counting
  // sort; then each owner's records, ordered by partner, merged with its listed partners (sorted).
  const IndexOfId index_of(id);
  struct Placed {
    std::uint32_t partner;
    std::uint32_t record;  // index into pairs, its high bit set when the owner is the record's `high`
  };
  constexpr std::uint32_t kFlip = 1u << 31;
  std::vector<std::uint32_t> start(n + 2, 0);
  std::vector<std::uint32_t> owner(pairs.size(), IndexOfId::kAbsent);
  std::vector<Placed> entry(pairs.size());
  for (std::size_t r = 0; r < pairs.size(); ++r) {
    const std::uint32_t a = index_of(pairs[r].low), b = index_of(pairs[r].high);
    if (a == IndexOfId::kAbsent || b == IndexOfId::kAbsent) continue;  // a particle removed
    owner[r] = std::min(a, b);
    entry[r] = {std::max(a, b), std::uint32_t(r) | (a > b ? kFlip : 0u)};
    ++start[owner[r] + 2];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Placed> placed(start[n + 1]);
  for (std::size_t r = 0; r < pairs.size(); ++r)
    if (owner[r] != IndexOfId::kAbsent) placed[start[owner[r] + 1]++] = entry[r];
  std::uint32_t found = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Placed* mine = placed.data() + start[i];
    Placed* mine_end = placed.data() + start[i + 1];
    std::sort(mine, mine_end, [](const Placed& x, const Placed& y) { return x.partner < y.partner; });
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1] && mine != mine_end; ++k) {
      while (mine != mine_end && mine->partner < list.partner[k]) ++mine;  // no longer within reach
      if (mine == mine_end || mine->partner != list.partner[k]) continue;
      const ContactHistory& h = pairs[mine->record & ~kFlip].history;
      contacts[found] = (mine->record & kFlip) ? flipped(h) : h;
      slot[k] = found++;
      ++mine;
    }
  }
  return found;
}

void HistoryArchive::restore_walls(WallList& list, const std::vector<std::int64_t>& id) const {
  const std::size_t n = list.first.size() - 1;
  list.history.assign(list.size(), ContactHistory{});
  if (walls.empty()) return;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      const WallRecord key{id[i], list.wall[k], {}};
      auto it = std::lower_bound(walls.begin(), walls.end(), key, [](const WallRecord& x, const WallRecord& y) {
        return x.particle != y.particle ? x.particle < y.particle : x.wall < y.wall;
      });
      if (it != walls.end() && it->particle == key.particle && it->wall == key.wall) list.history[k] = it->history;
    }
  }
}

CellSort sort_into_cells(const std::vector<Vec3>& positions, const Domain& domain, double cell_size) {
  CellSort s;
  const std::size_t n = positions.size();
  s.grid = CellGrid::covering(positions, domain, cell_size, 4 * n + 64);
  s.cell_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.cell_of[i] = s.grid.index(positions[i]);
  // Counting sort: stable, so the order within a cell follows the current index order.
  s.cell_start.assign(s.grid.total() + 1, 0);
  for (std::uint32_t c : s.cell_of) ++s.cell_start[c + 1];
  std::partial_sum(s.cell_start.begin(), s.cell_start.end(), s.cell_start.begin());
  s.order.resize(n);
  std::vector<std::uint32_t> fill(s.cell_start.begin(), s.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) s.order[fill[s.cell_of[i]]++] = static_cast<std::uint32_t>(i);
  return s;
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
    const std::size_t team = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t me = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t begin = n * me / team, end = n * (me + 1) / team;
    std::vector<std::uint32_t>& mine = found[me];
    mine.clear();
    std::array<std::uint32_t, 27> stencil;
    int stencil_size = 0;
    std::uint32_t stencil_of = ~0u;
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t cell = cells.cell_of[i];
      if (cell != stencil_of) {
        stencil_size = cells.grid.neighbours(cell, stencil);
        if (in_cell_order)
          stencil_size = int(std::remove_if(stencil.begin(), stencil.begin() + stencil_size,
                                            [cell](std::uint32_t c) { return c < cell; }) -
                             stencil.begin());
        stencil_of = cell;
      }
      const std::size_t before = mine.size();
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i] + skin;
      for (int c = 0; c < stencil_size; ++c) {
        for (std::uint32_t s = cells.cell_start[stencil[c]]; s < cells.cell_start[stencil[c] + 1]; ++s) {
          const std::uint32_t j = cells.order[s];
          if (j <= i) continue;
          Vec3 d = xi - p.position[j];
          if (periodic) d = domain.minimum_image(d);
          const double reach = ri + p.radius[j];
          if (norm2(d) < reach * reach) mine.push_back(j);
        }
      }
      std::sort(mine.begin() + std::ptrdiff_t(before), mine.end());
      out.first[i + 1] = static_cast<std::uint32_t>(mine.size() - before);
    }
#pragma omp barrier
#pragma omp single
    {
      std::partial_sum(out.first.begin(), out.first.end(), out.first.begin());
      out.partner.resize(out.first[n]);
    }
    std::copy(mine.begin(), mine.end(), out.partner.begin() + out.first[begin]);
  }
  out.history.clear();
}

void build_wall_candidates(const Particles& p, const std::vector<Wall>& walls, double skin, WallList& out) {
  const std::size_t n = p.size();
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

std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Particles& p, const Domain& domain,
                                                                       double skin) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      const Vec3 d = domain.minimum_image(p.position[i] - p.position[j]);
      const double reach = p.radius[i] + p.radius[j] + skin;
      if (norm2(d) < reach * reach) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

}  // namespace trapdem
