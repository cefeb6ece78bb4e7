#pragma once
// Replicates: a case run with several packing seeds (`replicates = N`, optionally `seeds = [...]`),
// so that a trend between cases can be told from the seed-to-seed spread (issue 12, section 3).
//
// The request may stand at the study file's top level, in a scale's table or in a case's table;
// the most specific one that says anything decides (case, then scale, then study). Without any,
// a case runs once with its configuration's own seed in cases/<name>/, as before replicates
// existed. With one, replicate k (0-based) of a case whose resolved pluviation.seed is s0 runs with
//   seed_k = seeds[k]            if `seeds` is given,
//   seed_k = s0 + k              otherwise,
// in cases/<name>/seed-<seed_k>/ (docs/study.md). The derived seeds are distinct, and the same
// every time the study is run, so a re-run finds its replicates again; cases sharing a base seed
// share their seeds too (the same packings' randomness under different contact laws).
#include <cstdint>
#include <string>
#include <vector>

namespace trapdem {

class Config;

// Upper bounds (docs/study.md): each replicate is a whole run (minutes at the demo scale, days at
// the paper's), so more than 1000 per case is a slip, not a plan; a seed is written to summary.json
// as a JSON number (a double), exact up to 2^53 - 1.
inline constexpr std::int64_t kMaxReplicates = 1000;
inline constexpr std::int64_t kMaxSeed = (std::int64_t{1} << 53) - 1;

struct ReplicateRequest {
  std::int64_t count = 0;              // replicates; 0: this level does not ask
  std::vector<std::uint64_t> seeds;    // explicit seeds (then count == seeds.size()), or empty
  bool asked() const { return count > 0; }
};

// Reads `replicates` and `seeds` under `table` ("" for the document's top level) strictly: N in
// [1, kMaxReplicates], at most kMaxReplicates seeds, each an integer in [0, kMaxSeed], no duplicates, and as many as `replicates` says when both are
// given. Throws InputError naming the file, line and key.
ReplicateRequest read_replicate_request(Config& document, const std::string& table);

// The request that applies: the first of (case, scale, study) that asks; none asks: not asked.
const ReplicateRequest& applicable_request(const ReplicateRequest& study_case, const ReplicateRequest& scale,
                                           const ReplicateRequest& study);

// The seeds of the replicates (the rule above). Not asked: {case_seed}.
std::vector<std::uint64_t> replicate_seeds(const ReplicateRequest& request, std::uint64_t case_seed);

// The folder name of a replicate: "seed-<seed>".
std::string replicate_folder_name(std::uint64_t seed);

}  // namespace trapdem
