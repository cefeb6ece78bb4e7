#include "dem/history_archive.hpp"

#include <omp.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "dem/thread_block.hpp"

namespace trapdem {

namespace {
ContactHistory flipped(ContactHistory h) {
  h.tangential_spring = -h.tangential_spring;
  h.rolling_spring = -h.rolling_spring;
  return h;
}

// Archives pair k's history history_of(k) for the listed pairs that touch (touching(k)), in list
// order, by thread blocks of owners: each thread counts its block's, then writes them into place in
// `pairs` (its storage reused from the last call: a fresh vector of ~40 MB at 300k particles costs
// more in page faults than the copy).
template <class Touching, class HistoryOf>
void archive_pairs(const PairList& list, const std::vector<std::int64_t>& id, Touching touching, HistoryOf history_of,
                   std::vector<HistoryArchive::PairRecord>& pairs) {
  const std::size_t n = list.first.empty() ? 0 : list.first.size() - 1;
  std::vector<std::size_t> offset(static_cast<std::size_t>(omp_get_max_threads()) + 1, 0);
#pragma omp parallel
  {
    const int me = omp_get_thread_num(), threads = omp_get_num_threads();
    const auto [begin, end] = thread_block(n, me, threads);
    const std::uint32_t k_begin = n ? list.first[begin] : 0, k_end = n ? list.first[end] : 0;
    std::size_t mine = 0;
    for (std::uint32_t k = k_begin; k < k_end; ++k) mine += touching(k) ? 1 : 0;
    offset[std::size_t(me) + 1] = mine;
#pragma omp barrier
#pragma omp single
    {
      std::partial_sum(offset.begin(), offset.begin() + threads + 1, offset.begin());
      pairs.resize(offset[std::size_t(threads)]);
    }
    std::size_t at = offset[std::size_t(me)];
    for (std::size_t i = begin; i < end; ++i) {
      for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
        if (!touching(k)) continue;
        const ContactHistory h = history_of(k);
        const std::int64_t a = id[i], b = id[list.partner[k]];
        pairs[at++] = a < b ? HistoryArchive::PairRecord{a, b, h} : HistoryArchive::PairRecord{b, a, flipped(h)};
      }
    }
  }
}
}  // namespace

void HistoryArchive::store_pairs(const PairList& list, const ContactSlots& slot, const PairHistories& contacts,
                                 const std::vector<std::int64_t>& id) {
  archive_pairs(list, id, [&](std::uint32_t k) { return slot[k] != kNoContact; },
                [&](std::uint32_t k) { return contacts.get(slot[k]); }, pairs);
}

void HistoryArchive::store_pairs(const PairList& list, const std::vector<std::int64_t>& id) {
  archive_pairs(list, id, [&](std::uint32_t k) { return list.history[k].touching(); },
                [&](std::uint32_t k) { return list.history[k]; }, pairs);
}

void HistoryArchive::IndexOfId::index(const std::vector<std::int64_t>& id) {
  table_.clear();
  sorted_.clear();
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

std::uint32_t HistoryArchive::IndexOfId::operator()(std::int64_t particle_id) const {
  if (!table_.empty()) {
    if (particle_id < lowest_) return kAbsent;
    const auto at = static_cast<std::uint64_t>(particle_id) - static_cast<std::uint64_t>(lowest_);
    return at < table_.size() ? table_[at] : kAbsent;
  }
  auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::pair<std::int64_t, std::uint32_t>{particle_id, 0});
  return it != sorted_.end() && it->first == particle_id ? it->second : kAbsent;
}

void HistoryArchive::store_walls(const WallList& list, const std::vector<std::int64_t>& id) {
  walls.clear();
  const std::size_t n = list.first.empty() ? 0 : list.first.size() - 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k)
      if (list.history[k].touching()) walls.push_back({id[i], list.wall[k], list.history[k]});
}

std::size_t HistoryArchive::restore_pairs(const PairList& list, const std::vector<std::int64_t>& id,
                                          ContactSlots& slot, PairHistories& contacts) {
  index_of_.index(id);
  return restore_indexed_pairs(list, slot, contacts);
}

std::size_t HistoryArchive::restore(const PairList& pair_list, WallList& wall_list, const std::vector<std::int64_t>& id,
                                    ContactSlots& slot, PairHistories& contacts) {
  index_of_.index(id);
  restore_indexed_walls(wall_list);
  return restore_indexed_pairs(pair_list, slot, contacts);
}

std::size_t HistoryArchive::restore_indexed_pairs(const PairList& list, ContactSlots& slot, PairHistories& contacts) {
  const std::size_t n = list.first.size() - 1;
  slot.assign(list.size(), kNoContact);
  if (pairs.empty()) return 0;
  // Each record's pair in current indices, grouped by its owner (the lower index) with a counting
  // sort; then each owner's records, ordered by partner, merged with its listed partners (sorted).
  constexpr std::uint32_t kFlip = 1u << 31;
  start_.assign(n + 2, 0);
  owner_.assign(pairs.size(), IndexOfId::kAbsent);
  entry_.resize(pairs.size());
  for (std::size_t r = 0; r < pairs.size(); ++r) {
    const std::uint32_t a = index_of_(pairs[r].low), b = index_of_(pairs[r].high);
    if (a == IndexOfId::kAbsent || b == IndexOfId::kAbsent) continue;  // a particle removed
    owner_[r] = std::min(a, b);
    entry_[r] = {std::max(a, b), std::uint32_t(r) | (a > b ? kFlip : 0u)};
    ++start_[owner_[r] + 2];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  placed_.resize(start_[n + 1]);
  for (std::size_t r = 0; r < pairs.size(); ++r)
    if (owner_[r] != IndexOfId::kAbsent) placed_[start_[owner_[r] + 1]++] = entry_[r];
  std::uint32_t found = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Placed* mine = placed_.data() + start_[i];
    Placed* mine_end = placed_.data() + start_[i + 1];
    std::sort(mine, mine_end, [](const Placed& x, const Placed& y) { return x.partner < y.partner; });
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1] && mine != mine_end; ++k) {
      while (mine != mine_end && mine->partner < list.partner[k]) ++mine;  // no longer within reach
      if (mine == mine_end || mine->partner != list.partner[k]) continue;
      const ContactHistory& h = pairs[mine->record & ~kFlip].history;
      contacts.set(found, (mine->record & kFlip) ? flipped(h) : h);
      slot[k] = found++;
      ++mine;
    }
  }
  return found;
}

void HistoryArchive::restore_indexed_walls(WallList& list) {
  list.history.assign(list.size(), ContactHistory{});
  if (walls.empty()) return;
  // Each record to its particle's current index, then to that particle's candidate of the same
  // wall (a particle has at most kMaxWallCandidates): linear in the records.
  const std::size_t n = list.first.size() - 1;
  for (const WallRecord& r : walls) {
    const std::uint32_t i = index_of_(r.particle);
    if (i == IndexOfId::kAbsent || i >= n) continue;  // removed, or a ghost (no wall candidates)
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k)
      if (list.wall[k] == r.wall) list.history[k] = r.history;
  }
}

}  // namespace trapdem
