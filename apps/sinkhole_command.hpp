#pragma once
// `trapdem sinkhole --throat D --layer THICKNESS:ANGLE [--layer ...]`: the maximum surface diameter of
// a sinkhole by scenario supposition (Buttrick & Van Schalkwyk 1995, as SANS 1936 uses it) and its
// SANS 1936 size class. With `--from DIR`: the mechanism-based estimate from a DEM run (its surface
// zone of influence scaled to prototype by the g level) beside the supposition for the same geometry.
// See docs/sinkhole.md.
#include <string>
#include <vector>

namespace trapdem::app {

struct SinkholeOptions {
  std::string throat;               // length ("2.5", "2.5m"); not with --from
  std::vector<std::string> layers;  // "THICKNESS:ANGLE", cavity upward; with --from one ":ANGLE"
  std::string from;                 // a run folder with analysis/metrics.json
  bool json = false;                // JSON on stdout instead of the table
};

// The text the command prints (table or JSON). Throws InputError on bad input.
std::string sinkhole_report(const SinkholeOptions& options);

// The whole command. Returns the exit code.
int run_sinkhole(const SinkholeOptions& options);

}  // namespace trapdem::app
