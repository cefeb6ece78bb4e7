#include "study/strain_panel_of_runs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "plot/figure_format.hpp"
#include "plot/specimen_figures.hpp"
#include "study/run_analysis.hpp"

namespace fs = std::filesystem;

namespace trapdem {

RunPanel write_strain_panel_of_runs(const fs::path& out, const std::vector<fs::path>& dirs,
                                    const RunPanelOptions& o) {
  if (dirs.empty()) throw InputError("strain panel: give one or more run folders");
  plot::figure_format_of(out);  // a bad extension fails before the work
  if (!o.labels.empty() && o.labels.size() != dirs.size()) {
    throw InputError(fmt::format("--labels: {} labels for {} run folders (give one per folder, in order)",
                                 o.labels.size(), dirs.size()));
  }
  if (!(o.max_strain >= 0.0) || !std::isfinite(o.max_strain)) {
    throw InputError(fmt::format("--max-strain {}: expected the top of the colour scale, > 0 (0: automatic)",
                                 o.max_strain));
  }
  std::vector<AnalysisResult> results;
  results.reserve(dirs.size());
  for (const fs::path& dir : dirs) {
    AnalyzeOptions a;
    a.dir = dir.string();
    a.at = o.at;
    a.reference = o.reference;
    a.view = o.view;
    a.front_depth = o.front_depth;
    results.push_back(analyze_directory(a));
  }
  std::vector<const AnalysisResult*> pointers;
  RunPanel panel{results.size(), o.max_strain};
  for (const AnalysisResult& r : results) {
    pointers.push_back(&r);
    if (!(o.max_strain > 0.0)) panel.max_strain = std::max(panel.max_strain, plot::auto_strain_scale(r));
  }
  plot::write_strain_panel(out, pointers, o.labels, panel.max_strain);
  return panel;
}

}  // namespace trapdem
