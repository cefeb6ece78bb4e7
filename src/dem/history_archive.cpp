#include "dem/history_archive.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <utility>

namespace trapdem {

namespace {
ContactHistory flipped(ContactHistory h) {
  h.tangential_spring = -h.tangential_spring;
  h.rolling_spring = -h.rolling_spring;
  return h;
}

// Archives pair k's history history_of(k) for the listed pairs whose history_of(k) is not null.
template <class HistoryOf>
void archive_pairs(const PairList& list, const std::vector<std::int64_t>& id, HistoryOf history_of,
                   std::vector<HistoryArchive::PairRecord>& pairs) {
  pairs.clear();
  const std::size_t n = list.first.empty() ? 0 : list.first.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      const std::optional<ContactHistory> h = history_of(k);
      if (!h) continue;
      const std::int64_t a = id[i], b = id[list.partner[k]];
      pairs.push_back(a < b ? HistoryArchive::PairRecord{a, b, *h} : HistoryArchive::PairRecord{b, a, flipped(*h)});
    }
  }
}
}  // namespace

void HistoryArchive::store_pairs(const PairList& list, const ContactSlots& slot, const PairHistories& contacts,
                                 const std::vector<std::int64_t>& id) {
  archive_pairs(list, id, [&](std::uint32_t k) {
    return slot[k] == kNoContact ? std::nullopt : std::optional<ContactHistory>(contacts.get(slot[k]));
  }, pairs);
}

void HistoryArchive::store_pairs(const PairList& list, const std::vector<std::int64_t>& id) {
  archive_pairs(list, id, [&](std::uint32_t k) {
    return list.history[k].touching() ? std::optional<ContactHistory>(list.history[k]) : std::nullopt;
  }, pairs);
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
                                          ContactSlots& slot, PairHistories& contacts) const {
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
      contacts.set(found, (mine->record & kFlip) ? flipped(h) : h);
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

}  // namespace trapdem
