#pragma once
// The Verlet list of particle pairs: every pair within the interaction range plus a skin, built
// from the cell sort; rebuilt when two particles could have approached by the skin
// (Simulation::lists_outdated).
#include <cstdint>
#include <vector>

#include "dem/cell_sort.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/domain.hpp"
#include "dem/particles.hpp"

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

// The engine's form of the pairs' contact histories: a listed pair's slot is its index into an
// array of the touching pairs' histories, or kNoContact (most listed pairs do not touch).
inline constexpr std::uint32_t kNoContact = ~0u;
using ContactSlots = std::vector<std::uint32_t>;  // per listed pair

// Builds the half list of pairs closer than r_i + r_j + skin (minimum image on periodic axes).
void build_pairs(const Particles& p, const CellSort& cells, const Domain& domain, double skin, PairList& out);

// On a rank of a decomposition (the first `owned` particles its own, the rest ghosts): keeps the
// pairs this rank computes. A pair of two owned particles is computed here; a pair of an owned
// particle and a ghost is computed by the rank that owns the lower id of the two (its history is
// kept there and migrates with that particle); a pair of two ghosts, elsewhere. So each pair is
// computed once over all ranks. Ghosts follow the owned particles, so every owner kept is owned.
void keep_pairs_computed_here(PairList& list, std::size_t owned, const std::vector<std::int64_t>& id);

}  // namespace trapdem
