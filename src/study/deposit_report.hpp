#pragma once
// `trapdem deposit DIR`: the deposit of a run folder's fill, at each snapshot before the trapdoor
// moves (after pluviation, after settling at 1 g, after spin-up): bulk solid fraction, coordination
// number and rattlers, the surface height, the solid-fraction profile with height. Written to
// DIR/deposit.json; the table is what the command prints. The fill comparisons of
// docs/validation.md read these numbers.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/deposit.hpp"

namespace trapdem {

struct DepositAtSnapshot {
  std::string snapshot;  // group name
  std::string stage;
  double time = 0.0;     // s
  DepositMetrics metrics;
};

// Every snapshot of the folder taken before lowering began, and the first of lowering (the
// trapdoor still at 0). Throws InputError naming the folder if it has no snapshots or no
// resolved.toml.
std::vector<DepositAtSnapshot> measure_run_deposit(const std::filesystem::path& run_dir);

std::string deposit_table(const std::vector<DepositAtSnapshot>& deposits);
// Writes run_dir/deposit.json (atomically) and returns its path.
std::filesystem::path write_deposit_json(const std::filesystem::path& run_dir,
                                         const std::vector<DepositAtSnapshot>& deposits);

}  // namespace trapdem
