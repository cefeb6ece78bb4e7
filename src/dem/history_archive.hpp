#pragma once
// The contact histories keyed by particle ids, to survive a list rebuild in which indices change
// (re-ordering, particles added or removed).
#include <cstdint>
#include <utility>
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
  // Not const: it works in arrays kept from one call to the next (a rebuild at 300k particles
  // would otherwise fault ~60 MB of fresh pages in).
  std::size_t restore_pairs(const PairList& pairs, const std::vector<std::int64_t>& id, ContactSlots& slot,
                            PairHistories& contacts);
  // The pairs' as restore_pairs, and the walls' (each record onto its particle's candidate of the
  // same wall), the ids indexed once for the two: a list rebuild's. Returns restore_pairs' count.
  std::size_t restore(const PairList& pairs, WallList& walls, const std::vector<std::int64_t>& id,
                      ContactSlots& slot, PairHistories& contacts);

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

 private:
  // The current index of each particle id: a table when the ids are dense (the usual 1..N, any
  // order), else a search in the ids sorted. Its arrays are reused by the next index().
  class IndexOfId {
   public:
    static constexpr std::uint32_t kAbsent = ~0u;
    void index(const std::vector<std::int64_t>& id);
    std::uint32_t operator()(std::int64_t particle_id) const;

   private:
    std::int64_t lowest_ = 0;
    std::vector<std::uint32_t> table_;
    std::vector<std::pair<std::int64_t, std::uint32_t>> sorted_;
  };

  // With index_of_ indexed for `id`.
  std::size_t restore_indexed_pairs(const PairList& pairs, ContactSlots& slot, PairHistories& contacts);
  void restore_indexed_walls(WallList& walls);

  // restore_pairs' work arrays (history_archive.cpp), kept between calls.
  struct Placed {
    std::uint32_t partner;
    std::uint32_t record;  // index into pairs, its high bit set when the owner is the record's `high`
  };
  IndexOfId index_of_;
  std::vector<std::uint32_t> start_, owner_;
  std::vector<Placed> entry_, placed_;
};

}  // namespace trapdem
