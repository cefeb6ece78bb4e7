// The contact-history archive that carries the touching pairs' springs across a rebuild: stored
// from the compact form by particle id, restored into the compact form of a new list after the
// particles were shuffled (as a re-ordering does) and some removed. Every history must land on its
// own pair, turned to the new owner's side (a pair whose owner changed has its vectors negated),
// and packed in pair order. Exact: the values are copied, not computed. The engine's compact form
// keeps the rolling spring only for a law that has one (PairHistories): both forms are tested, and
// the archive from the per-listed-pair form (an MPI rank's checkpoint) too.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <string>

#include "dem/history_archive.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

// A history that names its pair (the two ids in its vectors), expressed for body `from`: the
// vectors of the lower id's side, negated for the other side.
ContactHistory history_of(std::int64_t from, std::int64_t to) {
  const double sign = from < to ? 1.0 : -1.0;
  const double low = double(std::min(from, to)), high = double(std::max(from, to));
  ContactHistory h;
  h.tangential_spring = sign * Vec3{low, high, 1.0};
  h.rolling_spring = sign * Vec3{-high, 0.5, low};
  h.flags = ContactHistory::kTouching | ((std::int64_t(low) + std::int64_t(high)) % 3 == 0 ? ContactHistory::kSliding : 0u);
  return h;
}

PairList list_of(const Particles& p, const Domain& domain, double skin) {
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  PairList list;
  build_pairs(p, sort_into_cells(p.position, domain, 2.0 * r_max + skin), domain, skin, list);
  return list;
}

enum class StoredFrom { compact, per_listed_pair };

void round_trip(const std::vector<std::int64_t>& ids, bool rolling_spring, StoredFrom from, const std::string& what) {
  SCOPED_TRACE(what);
  const Domain domain = box(0.008);
  Rng rng(11);
  Particles p;
  for (std::int64_t id : ids)
    p.add(id, {rng.uniform(0.0, 0.008), rng.uniform(0.0, 0.008), rng.uniform(0.0, 0.008)},
          rng.uniform(0.0004, 0.0008), 2500.0);
  const double skin = 0.0002;
  const PairList before = list_of(p, domain, skin);
  // About half the listed pairs touch; their histories, compact in pair order.
  ContactSlots slot(before.size(), kNoContact);
  PairHistories contacts(rolling_spring);
  contacts.grow_to(before.size());
  PairList per_pair = before;
  per_pair.history.assign(before.size(), ContactHistory{});
  std::uint32_t stored_count = 0;
  std::map<std::pair<std::int64_t, std::int64_t>, bool> stored;
  for (std::uint32_t i = 0; i + 1 < before.first.size(); ++i) {
    for (std::uint32_t k = before.first[i]; k < before.first[i + 1]; ++k) {
      if (rng.uniform() < 0.5) continue;
      const std::int64_t a = p.id[i], b = p.id[before.partner[k]];
      slot[k] = stored_count++;
      contacts.set(slot[k], history_of(a, b));
      per_pair.history[k] = history_of(a, b);
      stored[{std::min(a, b), std::max(a, b)}] = true;
    }
  }
  ASSERT_GT(stored_count, 200u);
  HistoryArchive archive;
  if (from == StoredFrom::compact)
    archive.store_pairs(before, slot, contacts, p.id);
  else
    archive.store_pairs(per_pair, p.id);

  // Shuffle the particles and drop a tenth of them.
  std::vector<std::uint32_t> keep(p.size());
  std::iota(keep.begin(), keep.end(), 0u);
  for (std::size_t k = keep.size() - 1; k > 0; --k) std::swap(keep[k], keep[rng.next() % (k + 1)]);
  keep.resize(keep.size() * 9 / 10);
  p.permute(keep);
  const PairList after = list_of(p, domain, skin);

  ContactSlots restored_slot;
  PairHistories restored(rolling_spring);
  restored.grow_to(after.size() + 1);
  const std::size_t found = archive.restore_pairs(after, p.id, restored_slot, restored);
  ASSERT_EQ(restored_slot.size(), after.size());
  std::size_t expected_found = 0;
  std::uint32_t next = 0;
  for (std::uint32_t i = 0; i + 1 < after.first.size(); ++i) {
    for (std::uint32_t k = after.first[i]; k < after.first[i + 1]; ++k) {
      const std::int64_t a = p.id[i], b = p.id[after.partner[k]];
      const bool was_stored = stored.count({std::min(a, b), std::max(a, b)}) > 0;
      if (!was_stored) {
        EXPECT_EQ(restored_slot[k], kNoContact) << "pair " << a << "-" << b << " had no history";
        continue;
      }
      ++expected_found;
      ASSERT_EQ(restored_slot[k], next) << "pair " << a << "-" << b << ": not packed in pair order";
      ++next;
      const ContactHistory want = history_of(a, b);
      const ContactHistory got = restored.get(restored_slot[k]);
      EXPECT_EQ(got.tangential_spring.x, want.tangential_spring.x) << "pair " << a << "-" << b;
      EXPECT_EQ(got.tangential_spring.y, want.tangential_spring.y) << "pair " << a << "-" << b;
      EXPECT_EQ(got.tangential_spring.z, want.tangential_spring.z) << "pair " << a << "-" << b;
      if (rolling_spring) {
        EXPECT_EQ(got.rolling_spring.x, want.rolling_spring.x) << "pair " << a << "-" << b;
        EXPECT_EQ(got.rolling_spring.z, want.rolling_spring.z) << "pair " << a << "-" << b;
      } else {  // a law without a rolling spring keeps none: it reads back as zero
        EXPECT_EQ(norm2(got.rolling_spring), 0.0) << "pair " << a << "-" << b;
      }
      EXPECT_EQ(got.flags, want.flags) << "pair " << a << "-" << b;
    }
  }
  EXPECT_EQ(found, expected_found);
  EXPECT_GT(expected_found, 150u) << "too few pairs survived to test anything";
  report("{}: {} histories stored, {} restored after shuffling and removing a tenth", what, stored_count, found);
}

}  // namespace

TEST(HistoryArchive, RestoresEveryHistoryOnItsPairAfterShuffleAndRemoval) {
  std::vector<std::int64_t> dense(700);
  std::iota(dense.begin(), dense.end(), 1);
  std::vector<std::int64_t> reversed(dense.rbegin(), dense.rend());
  std::vector<std::int64_t> sparse;
  for (std::int64_t k = 0; k < 700; ++k) sparse.push_back(1000003 * ((k * 389) % 700) - 5000000);
  // The archive is written by thread blocks of owners: the same records at every count.
  const int threads_before = omp_get_max_threads();
  for (const int threads : {1, 3, 7}) {
    omp_set_num_threads(threads);
    const std::string on = fmt::format(", {} threads", threads);
    for (const bool rolling : {true, false}) {
      const std::string law = rolling ? "rolling spring kept (EPSD)" : "no rolling spring";
      round_trip(dense, rolling, StoredFrom::compact, "ids 1..700, " + law + on);
      round_trip(reversed, rolling, StoredFrom::compact, "ids 700..1 (owners change sides), " + law + on);
      round_trip(sparse, rolling, StoredFrom::compact,
                 "sparse ids, negative ones too (looked up by search, not table), " + law + on);
    }
    round_trip(dense, true, StoredFrom::per_listed_pair, "ids 1..700, from the per-listed-pair form" + on);
    round_trip(reversed, true, StoredFrom::per_listed_pair, "ids 700..1, from the per-listed-pair form" + on);
  }
  omp_set_num_threads(threads_before);
}

// The wall histories, through restore() (the rebuild's one call for pairs and walls, the ids
// indexed once): each lands on its particle's candidate of the same wall after the particles were
// shuffled and some removed; a candidate without a stored history starts untouched.
TEST(HistoryArchive, RestoresWallHistoriesOnTheirParticleAndWall) {
  const std::vector<std::int64_t> ids = {40, 7, 13, 2, 99, 61};  // sparse, not in order
  // Particle i has candidates of walls 0..(i % 3), each touching with a history naming (id, wall).
  auto wall_history = [](std::int64_t id, std::uint32_t wall) {
    ContactHistory h;
    h.tangential_spring = Vec3{double(id), double(wall), -1.0};
    h.flags = ContactHistory::kTouching;
    return h;
  };
  auto candidates_of = [](const std::vector<std::int64_t>& order) {
    WallList list;
    list.first.push_back(0);
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::uint32_t w = 0; w <= std::uint32_t(order[i] % 3); ++w) list.wall.push_back(w);
      list.first.push_back(std::uint32_t(list.wall.size()));
    }
    return list;
  };
  WallList before = candidates_of(ids);
  before.history.resize(before.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::uint32_t k = before.first[i]; k < before.first[i + 1]; ++k)
      if (before.wall[k] != 1) before.history[k] = wall_history(ids[i], before.wall[k]);  // wall 1: not touching
  HistoryArchive archive;
  archive.store_walls(before, ids);
  EXPECT_EQ(archive.walls.size(), 7u);  // (id % 3 + 1) candidates each: 2+2+2+3+1+2 = 12, less the 5 of wall 1

  const std::vector<std::int64_t> after_ids = {61, 2, 40, 13, 8};  // shuffled, 7 and 99 gone, 8 new
  WallList after = candidates_of(after_ids);
  PairList no_pairs;
  no_pairs.first.assign(after_ids.size() + 1, 0);
  ContactSlots slot;
  PairHistories contacts(false);
  EXPECT_EQ(archive.restore(no_pairs, after, after_ids, slot, contacts), 0u);
  ASSERT_EQ(after.history.size(), after.size());
  for (std::size_t i = 0; i < after_ids.size(); ++i) {
    for (std::uint32_t k = after.first[i]; k < after.first[i + 1]; ++k) {
      const bool stored = after.wall[k] != 1 && after_ids[i] != 8;
      const ContactHistory want = stored ? wall_history(after_ids[i], after.wall[k]) : ContactHistory{};
      EXPECT_EQ(after.history[k].tangential_spring.x, want.tangential_spring.x) << "id " << after_ids[i] << " wall " << after.wall[k];
      EXPECT_EQ(after.history[k].tangential_spring.y, want.tangential_spring.y) << "id " << after_ids[i] << " wall " << after.wall[k];
      EXPECT_EQ(after.history[k].flags, want.flags) << "id " << after_ids[i] << " wall " << after.wall[k];
    }
  }
}
