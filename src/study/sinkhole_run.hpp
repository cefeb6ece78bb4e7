#pragma once
// The sinkhole estimate's view of a DEM run folder: the specimen from resolved.toml (through
// RunFolder and the experiment's configuration reader) and the zone of influence and band angles
// from analysis/metrics.json (`trapdem analyze`). `trapdem sinkhole --from DIR` and the study report.
#include <filesystem>

#include "analysis/sinkhole.hpp"

namespace trapdem {

// Throws InputError if `dir` is not a folder, if resolved.toml is missing, or if analysis/metrics.json
// is missing ("run `trapdem analyze DIR` first") or lacks the zone of influence at the surface.
DemRunGeometry read_dem_run(const std::filesystem::path& dir);

}  // namespace trapdem
