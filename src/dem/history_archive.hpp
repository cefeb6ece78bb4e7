#pragma once
// The contact histories keyed by particle ids, to survive a list rebuild in which indices change
// (re-ordering, particles added or removed).
#include <cstdint>
#include <vector>

#include "dem/contact/contact_history.hpp"
#include "dem/pair_histories.hpp"
#include "dem/pair_list.hpp"
#include "dem/wall_list.hpp"

namespace trapdem {

class HistoryArchive {
 public:
  // From the compact form: pair k's history is contacts.get(slot[k]) where slot[k] != kNoContact.
  void store_pairs(const PairList& pairs, const ContactSlots& slot, const PairHistories& contacts,
                   const std::vector<std::int64_t>& id);
  // From the per-listed-pair form (PairList::history, as Simulation::pairs() gives it): the touching ones.
  void store_pairs(const PairList& pairs, const std::vector<std::int64_t>& id);
  void store_walls(const WallList& walls, const std::vector<std::int64_t>& id);
  // Into the compact form: slot[k] for every listed pair; the histories found packed at the front of
  // `contacts` (room for pairs.size() entries) in pair order. Returns how many were found.
  std::size_t restore_pairs(const PairList& pairs, const std::vector<std::int64_t>& id, ContactSlots& slot,
                            PairHistories& contacts) const;
  void restore_walls(WallList& walls, const std::vector<std::int64_t>& id) const;

  struct PairRecord {
    std::int64_t low, high;   // ids, low < high; the history is expressed for `low` as body i
    ContactHistory history;
  };
  struct WallRecord {
    std::int64_t particle;
    std::uint32_t wall;
    ContactHistory history;
  };
  std::vector<PairRecord> pairs;
  std::vector<WallRecord> walls;
};

}  // namespace trapdem
