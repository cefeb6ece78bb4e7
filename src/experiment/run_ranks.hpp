#pragma once
// The processes (ranks) one run spans, as the experiment and its run folder see them: the
// decomposition of the experiment's Simulation, the particles gathered for output, checkpoints
// of the whole state, and the agreements that keep every rank at the same point (a decision taken
// on rank 0's clock, an error on one rank thrown on all). It names no message-passing library:
// the MPI implementation is src/parallel (MpiRunRanks). Without one (a null RunRanks*) a run is
// one process, exactly as always. docs/ARCHITECTURE.md, "Many processes".
//
// Every call is collective: all ranks make it, in the same order.
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"
#include "io/checkpoint.hpp"

namespace trapdem {

class RunRanks {
 public:
  virtual ~RunRanks() = default;

  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  bool root() const { return rank() == 0; }

  // The decomposition each rank attaches to the experiment's Simulation before its first step.
  virtual std::unique_ptr<Decomposition> decomposition() = 0;

  // Every rank's owned particles in id order, on rank 0 (empty on the others).
  virtual Particles gather(const Simulation& sim) = 0;
  // Every rank's owned particles: how many.
  virtual std::size_t particle_count(const Simulation& sim) = 0;

  // The whole state (particles in id order, histories by ids, each rank's own state), written by
  // rank 0 atomically to `path`; a failure there is thrown on every rank.
  virtual void save_checkpoint(const std::filesystem::path& path, const Simulation& sim,
                               const std::map<std::string, std::string>& metadata) = 0;
  // Puts rank 0's checkpoint (read there; the others pass nothing) into every rank's Simulation,
  // built as the checkpointed run's was: on the same rank count each rank continues bit for bit
  // from its own state, on another the particles and histories are redistributed. Returns the
  // checkpoint's metadata on every rank.
  virtual std::map<std::string, std::string> restore_checkpoint(std::optional<Checkpoint> on_root,
                                                                Simulation& sim) = 0;

  // Throws on every rank the error of the lowest rank that passes one (its type kept: input,
  // simulation, file or other), or returns when none does.
  virtual void agree(std::exception_ptr local) = 0;
  virtual bool broadcast(bool root_value) = 0;  // rank 0's value on every rank
  virtual bool any(bool local) = 0;             // true on every rank when it is on one
  // Every rank's values one after the other, rank by rank, on rank 0 (empty on the others).
  virtual std::vector<double> gather_on_root(const std::vector<double>& values) = 0;
};

// Runs `work` on every rank (or only in the one process, without ranks) and agrees on its
// failure: when it throws on any rank, every rank throws the lowest such rank's error.
inline void agreed(RunRanks* ranks, const std::function<void()>& work) {
  if (!ranks) {
    work();
    return;
  }
  std::exception_ptr failure;
  try {
    work();
  } catch (...) {
    failure = std::current_exception();
  }
  ranks->agree(failure);
}

// The same for work that only rank 0 does (writing the run folder's files).
inline void on_root(RunRanks* ranks, const std::function<void()>& work) {
  agreed(ranks, [&] {
    if (!ranks || ranks->root()) work();
  });
}

}  // namespace trapdem
