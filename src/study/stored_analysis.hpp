#pragma once
// The analysis a finished run keeps after its snapshots are gone. snapshots.h5 is most of a run's
// size (hundreds of MB at paper scale) and is what one deletes, or does not copy back from a
// cluster; analysis/metrics.json is kept with the light results (scripts/publish-study.sh). The
// study report takes a run's numbers from that file when snapshots.h5 is missing, but only when
// the file is the analysis the report would have made: the last snapshot at the end of lowering,
// from the start of lowering, with every analysis setting at its default (a `trapdem analyze
// --at 40mm` or `--grid 2mm` left there would be other numbers under the same names).
#include <optional>
#include <string>

#include "core/json.hpp"
#include "experiment/run_folder.hpp"

namespace trapdem {

struct StoredAnalysis {
  std::optional<Json> metrics;  // the run's analysis/metrics.json, if usable
  std::string note;             // why it is not usable, or where the numbers came from
};

// The stored analysis of a finished run (call when the run's snapshots are missing). Throws
// nothing for a missing or unsuitable file: `note` says what is wrong, naming the file and key.
StoredAnalysis stored_final_analysis(const RunFolder& run);

}  // namespace trapdem
