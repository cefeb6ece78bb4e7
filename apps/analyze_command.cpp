#include "analyze_command.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
#include "core/errors.hpp"
#include "plot/figure_format.hpp"
#include "plot/specimen_figures.hpp"
#include "study/ground_reaction_overlay.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

int run_analyze(const AnalyzeOptions& o) {
  std::vector<fs::path> written;
  const AnalysisResult r = analyze_and_write(o, &written);
  const fs::path out = analysis_output_dir(o);
  if (!o.quiet) {
    std::fputs(metrics_table(r).c_str(), stdout);
    fmt::print("  written: ");
    for (std::size_t k = 0; k < written.size(); ++k) fmt::print("{}{}", k ? ", " : "", written[k].filename().string());
    fmt::print(" in {}\n", out.string());
  }
  return 0;
}

int run_figure(const FigureOptions& o) {
  if (o.dirs.empty()) throw InputError("trapdem figure: give one or more run folders");
  const fs::path out = o.out.empty() ? fs::path(o.grc ? "grc.png" : "panel.png") : fs::path(o.out);
  plot::figure_format_of(out);  // a bad extension fails before the work
  if (!o.labels.empty() && o.labels.size() != o.dirs.size()) {
    throw InputError(fmt::format("--labels: {} labels for {} run folders (give one per folder, in order)",
                                 o.labels.size(), o.dirs.size()));
  }
  if (o.grc) {
    const std::vector<fs::path> dirs(o.dirs.begin(), o.dirs.end());
    const auto legend = write_ground_reaction_overlay(out, dirs, o.labels);
    fmt::print("ground reaction curves of {} runs written to {}\n", legend.size(), out.string());
    return 0;
  }
  std::vector<AnalysisResult> results;
  for (const auto& dir : o.dirs) {
    AnalyzeOptions a;
    a.dir = dir;
    a.at = o.at;
    a.reference = o.reference;
    a.view = o.view;
    a.front_depth = o.front_depth;
    results.push_back(analyze_directory(a));
  }
  std::vector<const AnalysisResult*> pointers;
  double vmax = o.max_strain;
  for (const auto& r : results) {
    pointers.push_back(&r);
    if (!(o.max_strain > 0.0)) vmax = std::max(vmax, plot::auto_strain_scale(r));
  }
  plot::write_strain_panel(out, pointers, o.labels, vmax);
  fmt::print("panel of {} runs (gamma_max scale 0 to {:g}) written to {}\n", results.size(), vmax, out.string());
  return 0;
}

}  // namespace trapdem::app
