#include "analyze_command.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
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
  const fs::path out = o.out.empty() ? fs::path(o.grc ? "grc.png" : "panel.png") : fs::path(o.out);
  const std::vector<fs::path> dirs(o.dirs.begin(), o.dirs.end());
  if (o.grc) {
    const auto legend = write_ground_reaction_overlay(out, dirs, o.panel.labels);
    fmt::print("ground reaction curves of {} runs written to {}\n", legend.size(), out.string());
    return 0;
  }
  const RunPanel panel = write_strain_panel_of_runs(out, dirs, o.panel);
  fmt::print("panel of {} runs (gamma_max scale 0 to {:g}) written to {}\n", panel.runs, panel.max_strain, out.string());
  return 0;
}

}  // namespace trapdem::app
