// The cell-list neighbour search against the brute-force O(N^2) reference: the same set of pairs
// closer than r_i + r_j + skin, on random polydisperse packings (radius ratio 3), bounded and
// periodic. Exact set equality: both use the same distance test, so there is no tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "dem/cell_sort.hpp"
#include "dem/pair_list.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

// Random spheres with radii in [r_min, 3 r_min], centres uniform in `region` (no overlap control:
// a dense random cloud exercises every distance).
Particles random_cloud(std::size_t n, const Domain& region, double r_min, std::uint64_t seed) {
  Particles p;
  Rng rng(seed);
  for (std::size_t i = 0; i < n; ++i)
    p.add(std::int64_t(i),
          {rng.uniform(region.lower.x, region.upper.x), rng.uniform(region.lower.y, region.upper.y),
           rng.uniform(region.lower.z, region.upper.z)},
          rng.uniform(r_min, 3.0 * r_min), 2500.0);
  return p;
}

// Builds the list as the engine does (cells of 2 r_max + skin) and checks its internal structure.
PairSet cell_list_pairs(const Particles& p, const Domain& domain, double skin) {
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  const CellSort cells = sort_into_cells(p.position, domain, 2.0 * r_max + skin);
  // The sort is a permutation grouping particles by cell.
  std::vector<std::uint32_t> order = cells.order;
  std::sort(order.begin(), order.end());
  for (std::uint32_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], k);

  PairList list;
  build_pairs(p, cells, domain, skin, list);
  EXPECT_EQ(list.first.size(), p.size() + 1);
  PairSet pairs;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      EXPECT_GT(list.partner[k], i) << "half list: partner must follow its owner";
      EXPECT_EQ(list.owner_of(k), i);
      EXPECT_TRUE(pairs.emplace(i, list.partner[k]).second) << "pair listed twice: " << i << ", " << list.partner[k];
    }
  }
  return pairs;
}

PairSet brute_force(const Particles& p, const Domain& domain, double skin) {
  const auto v = brute_force_pairs(p, domain, skin);
  return PairSet(v.begin(), v.end());
}

void expect_same_pairs_as_given(const Particles& p, const Domain& domain, double skin, const std::string& what) {
  const PairSet cells = cell_list_pairs(p, domain, skin);
  const PairSet reference = brute_force(p, domain, skin);
  EXPECT_GT(reference.size(), p.size() / 2) << what << ": too sparse to test anything";
  std::vector<std::pair<std::uint32_t, std::uint32_t>> missing, extra;
  std::set_difference(reference.begin(), reference.end(), cells.begin(), cells.end(), std::back_inserter(missing));
  std::set_difference(cells.begin(), cells.end(), reference.begin(), reference.end(), std::back_inserter(extra));
  EXPECT_TRUE(missing.empty()) << what << ": " << missing.size() << " pairs missed, first (" << missing[0].first << ", "
                               << missing[0].second << ")";
  EXPECT_TRUE(extra.empty()) << what << ": " << extra.size() << " pairs too many";
  report("{}: {} pairs, {} missing, {} extra", what, reference.size(), missing.size(), extra.size());
}

// As given (particles in no spatial order: build_pairs searches every neighbour cell) and in cell
// order, as the engine keeps them (it searches only the cells at or above the particle's own).
void expect_same_pairs(const Particles& p, const Domain& domain, double skin, const std::string& what) {
  expect_same_pairs_as_given(p, domain, skin, what);
  Particles sorted = p;
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  sorted.permute(sort_into_cells(p.position, domain, 2.0 * r_max + skin).order);
  const CellSort cells = sort_into_cells(sorted.position, domain, 2.0 * r_max + skin);
  ASSERT_TRUE(std::is_sorted(cells.cell_of.begin(), cells.cell_of.end()));
  expect_same_pairs_as_given(sorted, domain, skin, what + " (in cell order)");
}

}  // namespace

TEST(NeighborList, BoundedPolydisperseMatchesBruteForce) {
  const Domain region = box(0.01);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Particles p = random_cloud(600, region, 0.0004, seed);
    expect_same_pairs(p, region, 0.0002, "bounded");
    expect_same_pairs(p, region, 0.0, "bounded, no skin");
  }
}

TEST(NeighborList, PeriodicPolydisperseMatchesBruteForce) {
  Domain d = box(0.006);
  d.periodic[0] = d.periodic[1] = d.periodic[2] = true;
  for (std::uint64_t seed : {4u, 5u}) {
    const Particles p = random_cloud(500, d, 0.0004, seed);
    expect_same_pairs(p, d, 0.0002, "periodic xyz");
  }
  // Mixed: periodic along x only, bounded along y and z.
  Domain mixed = box(0.006);
  mixed.periodic[0] = true;
  expect_same_pairs(random_cloud(500, mixed, 0.0004, 6), mixed, 0.0002, "periodic x");
  // The smallest periodic box the engine accepts (two cells per axis, where the -1 and +1
  // neighbour cells are the same cell and must be visited once).
  const double cell = 2.0 * 0.0012 + 0.0002;
  Domain small;
  small.lower = {0, 0, 0};
  small.upper = {2.0 * cell, 2.0 * cell, 2.0 * cell};
  small.periodic[0] = small.periodic[1] = small.periodic[2] = true;
  expect_same_pairs(random_cloud(60, small, 0.0004, 7), small, 0.0002, "periodic, 2 cells per axis");
}

// A stray particle far away makes the bounding box huge; the grid then enlarges its cells to cap
// their number. The pairs must still all be found.
TEST(NeighborList, StrayParticleFarAwayMatchesBruteForce) {
  Particles p = random_cloud(400, box(0.005), 0.0004, 8);
  p.add(400, {0.9, -0.7, 0.5}, 0.0004, 2500.0);
  p.add(401, {0.9, -0.7, 0.5009}, 0.0004, 2500.0);  // and a pair out there (reach 1 mm)
  Domain big = box(1.0);
  expect_same_pairs(p, big, 0.0002, "stray particles");
  const PairSet pairs = cell_list_pairs(p, big, 0.0002);
  EXPECT_TRUE(pairs.count({400, 401}));
}

// The engine re-orders the particles by the sort and then takes the sort of the re-ordered
// particles from it (in_cell_order) instead of sorting again: it must be what sorting gives.
TEST(NeighborList, TheSortOfReorderedParticlesIsTheSortAgain) {
  const Domain region = box(0.01);
  Particles p = random_cloud(900, region, 0.0004, 11);
  const double cell = 2.0 * 0.0012 + 0.0002;
  const CellSort sorted = sort_into_cells(p.position, region, cell);
  p.permute(sorted.order);
  const CellSort again = sort_into_cells(p.position, region, cell);
  const CellSort derived = in_cell_order(sorted);
  EXPECT_EQ(derived.cell_of, again.cell_of);
  EXPECT_EQ(derived.cell_start, again.cell_start);
  EXPECT_EQ(derived.order, again.order);
  EXPECT_EQ(derived.grid.total(), again.grid.total());
  EXPECT_TRUE(std::is_sorted(derived.cell_of.begin(), derived.cell_of.end()));
}
