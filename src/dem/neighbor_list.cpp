#include "dem/neighbor_list.hpp"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "dem/errors.hpp"

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

namespace {
bool id_order(const HistoryArchive::PairRecord& x, const HistoryArchive::PairRecord& y) {
  return x.low != y.low ? x.low < y.low : x.high < y.high;
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
  std::sort(pairs.begin(), pairs.end(), id_order);
}

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
  // The look-ups in parallel, each pair's record index in its slot; then the histories packed in
  // pair order.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      const std::int64_t a = id[i], b = id[list.partner[k]];
      const PairRecord key{std::min(a, b), std::max(a, b), {}};
      auto it = std::lower_bound(pairs.begin(), pairs.end(), key, id_order);
      if (it != pairs.end() && it->low == key.low && it->high == key.high)
        slot[k] = static_cast<std::uint32_t>(it - pairs.begin());
    }
  }
  std::uint32_t found = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      if (slot[k] == kNoContact) continue;
      const PairRecord& record = pairs[slot[k]];
      contacts[found] = id[i] < id[list.partner[k]] ? record.history : flipped(record.history);
      slot[k] = found++;
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

namespace {
// Visits the partners j > i of particle i within r_i + r_j + skin, in a fixed order.
template <class Visit>
void for_each_partner(std::uint32_t i, const Particles& p, const CellSort& cells, const Domain& domain, double skin,
                      bool periodic, Visit&& visit) {
  std::array<std::uint32_t, 27> stencil;
  const int count = cells.grid.neighbours(cells.cell_of[i], stencil);
  std::sort(stencil.begin(), stencil.begin() + count);
  const Vec3 xi = p.position[i];
  const double ri = p.radius[i] + skin;
  for (int c = 0; c < count; ++c) {
    for (std::uint32_t s = cells.cell_start[stencil[c]]; s < cells.cell_start[stencil[c] + 1]; ++s) {
      const std::uint32_t j = cells.order[s];
      if (j <= i) continue;
      Vec3 d = xi - p.position[j];
      if (periodic) d = domain.minimum_image(d);
      const double reach = ri + p.radius[j];
      if (norm2(d) < reach * reach) visit(j);
    }
  }
}
}  // namespace

void build_pairs(const Particles& p, const CellSort& cells, const Domain& domain, double skin, PairList& out) {
  const std::size_t n = p.size();
  const bool periodic = domain.any_periodic();
  out.first.assign(n + 1, 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t count = 0;
    for_each_partner(static_cast<std::uint32_t>(i), p, cells, domain, skin, periodic, [&](std::uint32_t) { ++count; });
    out.first[i + 1] = count;
  }
  std::partial_sum(out.first.begin(), out.first.end(), out.first.begin());
  out.partner.resize(out.first[n]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t k = out.first[i];
    for_each_partner(static_cast<std::uint32_t>(i), p, cells, domain, skin, periodic,
                     [&](std::uint32_t j) { out.partner[k++] = j; });
    std::sort(out.partner.begin() + out.first[i], out.partner.begin() + out.first[i + 1]);
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
