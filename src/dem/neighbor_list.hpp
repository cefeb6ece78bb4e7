#pragma once
// Verlet lists: the particle pairs and particle-wall candidates within the interaction range plus
// a skin, with the contact history each carries. Rebuilt when something has moved half the skin;
// the history is carried across rebuilds and re-orderings by particle id.
#include <cstdint>
#include <vector>

#include "dem/cell_grid.hpp"
#include "dem/contact_kernel.hpp"
#include "dem/domain.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace trapdem {

// Half list in CSR form: particle i's pairs are (i, partner[k]) for k in [first[i], first[i+1]),
// each with partner[k] > i, so each pair is listed once.
struct PairList {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> partner;
  // Per listed pair, for tools and checkpoints (Simulation::pairs()). build_pairs() leaves it
  // empty: the engine keeps only the touching pairs' histories (see ContactSlots).
  std::vector<ContactHistory> history;

  std::size_t size() const { return partner.size(); }
  std::uint32_t owner_of(std::size_t pair) const;  // binary search in first (slow; tools and tests)
};

// The most walls one particle may have within reach (a corner of a box has three).
inline constexpr std::uint32_t kMaxWallCandidates = 16;

// Per particle, the walls within reach: wall[k] for k in [first[i], first[i+1]).
struct WallList {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> wall;
  std::vector<ContactHistory> history;
  std::vector<Vec3> force;   // N, force on the particle from this wall in the last step

  std::size_t size() const { return wall.size(); }
};

// The engine's form of the pairs' contact histories: a listed pair's slot is its index into an
// array of the touching pairs' histories, or kNoContact (most listed pairs do not touch).
inline constexpr std::uint32_t kNoContact = ~0u;
using ContactSlots = std::vector<std::uint32_t>;  // per listed pair

// Contact history keyed by particle ids, to survive a rebuild in which indices change.
class HistoryArchive {
 public:
  // From the compact form: pair k's history is contacts[slot[k]] where slot[k] != kNoContact.
  void store_pairs(const PairList& pairs, const ContactSlots& slot, const ContactHistory* contacts,
                   const std::vector<std::int64_t>& id);
  void store_walls(const WallList& walls, const std::vector<std::int64_t>& id);
  // Into the compact form: slot[k] for every listed pair; the histories found packed at the front of
  // `contacts` (room for pairs.size() entries) in pair order. Returns how many were found.
  std::size_t restore_pairs(const PairList& pairs, const std::vector<std::int64_t>& id, ContactSlots& slot,
                            ContactHistory* contacts) const;
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

// The spatial sort: cell of every particle and the permutation that groups them cell by cell.
struct CellSort {
  CellGrid grid;
  std::vector<std::uint32_t> cell_of;        // per particle
  std::vector<std::uint32_t> cell_start;     // CSR over cells into `order`
  std::vector<std::uint32_t> order;          // particle indices, cell by cell
};
CellSort sort_into_cells(const std::vector<Vec3>& positions, const Domain& domain, double cell_size);

// Builds the half list of pairs closer than r_i + r_j + skin (minimum image on periodic axes).
void build_pairs(const Particles& p, const CellSort& cells, const Domain& domain, double skin, PairList& out);
// Builds the particle-wall candidates closer than r_i + skin.
void build_wall_candidates(const Particles& p, const std::vector<Wall>& walls, double skin, WallList& out);

// Brute-force O(N^2) reference for tests: every pair (i < j) closer than r_i + r_j + skin.
std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Particles& p, const Domain& domain,
                                                                       double skin);

}  // namespace trapdem
