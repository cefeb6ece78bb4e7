#include "analyze_command.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
#include "core/errors.hpp"
#include "plot/specimen_figures.hpp"

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
  plot::write_strain_panel_png(o.out, pointers, vmax);
  fmt::print("panel of {} runs (gamma_max scale 0 to {:g}) written to {}\n", results.size(), vmax, o.out);
  return 0;
}

}  // namespace trapdem::app
