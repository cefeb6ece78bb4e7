#pragma once
// The analysis a finished run keeps after its snapshots are gone. snapshots.h5 is most of a run's
// size (hundreds of MB at paper scale) and is what one deletes, or does not copy back from a
// cluster; analysis/metrics.json is kept with the light results (scripts/publish-study.sh). The
// study report takes a run's numbers from that file when snapshots.h5 is missing, but only when
// the file is the analysis the report would have made: the last snapshot at the end of lowering,
// from the start of lowering, with every analysis setting at its default (a `trapdem analyze
// --at 40mm` or `--grid 2mm` left there would be other numbers under the same names). The figures
// `trapdem analyze` drew with that file (analysis/shear_strain.png, vertical_displacement.png, kept
// by `scripts/publish-study.sh --figures`) are the run's own pictures: the report shows them, each
// on its own colour scale, where it cannot draw its own. Its strain panel draws such a run from
// analysis/field_history.h5 (published with the metrics) on the panel's one colour scale.
#include <filesystem>
#include <optional>
#include <string>

#include "core/json.hpp"
#include "experiment/run_folder.hpp"
#include "plot/specimen_figures.hpp"

namespace trapdem {

struct StoredAnalysis {
  std::optional<Json> metrics;  // the run's analysis/metrics.json, if usable
  std::string note;             // why it is not usable, or where the numbers and figures came from
  // With usable metrics: the run's own figures beside them, as a page shows them (PNG, else SVG);
  // empty where there is none.
  std::filesystem::path strain_figure;        // analysis/shear_strain.png: total gamma_max at the end
  std::filesystem::path displacement_figure;  // analysis/vertical_displacement.png: contours at the end
  // With usable metrics and an analysis/field_history.h5 of the same analysis (its last layer the
  // metrics' snapshot, from the same reference): the total gamma_max there on its grid, smoothed
  // as the analysis smoothed it, for the report's panel (one colour scale with the other cases).
  std::optional<plot::StoredStrainMap> strain_map;
  std::string strain_map_note;  // why there is none, where metrics are usable
};

// The stored analysis of a finished run (call when the run's snapshots are missing). Throws
// nothing for a missing or unsuitable file: `note` says what is wrong, naming the file and key.
// The note names files relative to `names_relative_to` where one is given (a study's report names
// them from the study folder, cases/rf1/analysis/metrics.json: a published report is read on
// another machine, where the absolute path of the one that ran it means nothing).
StoredAnalysis stored_final_analysis(const RunFolder& run, const std::filesystem::path& names_relative_to = {});

}  // namespace trapdem
