#pragma once
// The MPI back end of the engine's domain decomposition (dem/decomposition.hpp): the box split
// into slabs along x, one per rank, with movable boundaries. Rank r owns the particles with
// bounds[r] <= x < bounds[r+1] (bounds[0] = -inf, bounds[R] = +inf: a particle leaving the box is
// caught by the engine's escape check, not lost between ranks). Ghosts come from the two
// neighbouring slabs only, so an interior slab must be at least the interaction range wide.
// Why slabs, and how another split would be added: docs/ARCHITECTURE.md ("Many processes").
#include <mpi.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"

namespace trapdem {

struct SlabSettings {
  // Interior boundaries (m, R - 1 ascending values); empty: balanced on the particles' x at adopt
  // (without particles: the domain's x split in equal slabs).
  std::vector<double> bounds;
  // At a list rebuild the boundaries move when the largest rank's particle count exceeds the mean
  // by more than this fraction (infinity: never).
  double rebalance_above = 0.1;
};

class SlabDecomposition final : public Decomposition {
 public:
  SlabDecomposition(MPI_Comm comm, SlabSettings settings);

  void adopt(Particles& p, const Domain& domain) override;
  bool owns(const Vec3& x) const override { return owner_of(x.x) == rank_; }
  void migrate(Particles& p, HistoryArchive& archive, double range) override;
  std::size_t exchange_ghosts(Particles& p, double range) override;
  void update_ghosts(Particles& p) override;
  void return_ghost_forces(Particles& p) override;
  bool any(bool local) override;
  void max(double* values, int count) override;
  using Decomposition::max;
  double sum(double local) override;
  void sum_wall_loads(std::vector<Wall>& walls) override;
  void agree_on_failure(const std::string& message) override;
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }

  // The state between steps (boundaries, the ghosts sent and received), for a checkpoint from
  // which this rank continues bit for bit; restore_state takes it on the same rank count.
  std::vector<std::uint8_t> save_state() const;
  void restore_state(const std::vector<std::uint8_t>& state);

  const std::vector<double>& bounds() const { return bounds_; }  // R + 1 values, m
  std::int64_t rebalances() const { return rebalances_; }

 private:
  int owner_of(double x) const;
  void rebalance(const Particles& p);
  bool migrate_one_hop(Particles& p, HistoryArchive& archive);

  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  SlabSettings settings_;
  std::vector<double> bounds_;
  bool balance_at_next_rebuild_ = false;
  std::int64_t rebalances_ = 0;
  // Between rebuilds: the owned particles sent as ghosts to the left and right neighbours, and how
  // many ghosts came from each (the left's first in the particle arrays).
  std::vector<std::uint32_t> send_[2];
  std::size_t received_[2] = {0, 0};
  std::size_t owned_ = 0;
  std::vector<double> send_buffer_[2], receive_buffer_[2];
};

// Attaches a SlabDecomposition of `comm` to the simulation (every rank calls it, before the first
// step, with the same simulation). Returns it (owned by the simulation).
SlabDecomposition& decompose_in_slabs(Simulation& sim, MPI_Comm comm, SlabSettings settings = {});

}  // namespace trapdem
