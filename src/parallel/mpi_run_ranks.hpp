#pragma once
// The MPI implementation of the ranks a run spans (experiment/run_ranks.hpp): slabs for the
// experiment's Simulation (SlabDecomposition), particles gathered to rank 0 for output,
// checkpoints of the whole state written by rank 0 and redistributed on resume, and the
// agreements (rank 0's decisions, errors) over one communicator.
#include <mpi.h>

#include "experiment/run_ranks.hpp"
#include "parallel/slab_decomposition.hpp"

namespace trapdem {

class MpiRunRanks final : public RunRanks {
 public:
  explicit MpiRunRanks(MPI_Comm comm, SlabSettings slabs = {});

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  std::unique_ptr<Decomposition> decomposition() override;
  Particles gather(const Simulation& sim) override;
  std::size_t particle_count(const Simulation& sim) override;
  void save_checkpoint(const std::filesystem::path& path, const Simulation& sim,
                       const std::map<std::string, std::string>& metadata) override;
  std::map<std::string, std::string> restore_checkpoint(std::optional<Checkpoint> on_root, Simulation& sim) override;
  void agree(std::exception_ptr local) override;
  bool broadcast(bool root_value) override;
  bool any(bool local) override;
  std::vector<double> gather_on_root(const std::vector<double>& values) override;

 private:
  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  SlabSettings slabs_;
  SlabDecomposition* slab_ = nullptr;  // the one handed out (owned by the simulation)
};

}  // namespace trapdem
