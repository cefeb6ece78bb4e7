#include "study/ground_reaction_overlay.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/length_text.hpp"
#include "experiment/ground_reaction.hpp"
#include "experiment/run_folder.hpp"
#include "io/text_file.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure_format.hpp"
#include "plot/line_chart.hpp"

namespace fs = std::filesystem;

namespace trapdem {

std::vector<std::string> ground_reaction_legend(const std::vector<fs::path>& dirs, const std::vector<std::string>& names,
                                                const std::vector<std::string>& labels) {
  if (!labels.empty() && labels.size() != dirs.size()) {
    throw InputError(fmt::format("--labels: {} labels for {} run folders (give one per folder, in order)",
                                 labels.size(), dirs.size()));
  }
  if (!labels.empty()) return labels;
  std::vector<std::string> legend;
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    const bool shared = std::count(names.begin(), names.end(), names[k]) > 1;
    const std::string folder = (dirs[k].filename().empty() ? dirs[k].parent_path() : dirs[k]).filename().string();
    legend.push_back(shared ? fmt::format("{} ({})", names[k], folder) : names[k]);
  }
  return legend;
}

std::vector<std::string> write_ground_reaction_overlay(const fs::path& out, const std::vector<fs::path>& dirs,
                                                       const std::vector<std::string>& labels) {
  if (dirs.empty()) throw InputError("trapdem figure --grc: give one or more run folders");
  plot::figure_format_of(out);  // a bad extension fails before the work
  std::vector<std::string> names;
  std::vector<std::vector<GroundReactionRow>> curves;
  std::vector<double> widths;
  for (const fs::path& dir : dirs) {
    const RunFolder run(dir);
    const ExperimentConfig specimen = run.specimen("the ground reaction curve needs the trapdoor width");
    if (!fs::exists(run.trapdoor_csv())) {
      throw InputError(fmt::format("{}: not found (a run folder written by `trapdem run` has it)",
                                   run.trapdoor_csv().string()));
    }
    curves.push_back(parse_ground_reaction_csv(read_text_file(run.trapdoor_csv()), run.trapdoor_csv().string()));
    if (curves.back().empty())
      throw InputError(fmt::format("{}: no rows after the header (the run has not reached its lowering): no curve to draw",
                                   run.trapdoor_csv().string()));
    names.push_back(specimen.name);
    widths.push_back(specimen.trapdoor.width);
  }
  const std::vector<std::string> legend = ground_reaction_legend(dirs, names, labels);
  plot::LineChart chart;
  chart.title = "Ground reaction curves";
  const bool one_width = std::all_of(widths.begin(), widths.end(), [&](double b) { return b == widths.front(); });
  chart.subtitle = fmt::format("trapdoor stress σ over its value before lowering σ0; {}",
                               one_width ? "B = " + format_mm(widths.front()) : "each run's own trapdoor width B");
  chart.x_label = "trapdoor displacement δ/B (-)";
  chart.y_label = "trapdoor stress ratio σ/σ0 (-)";
  chart.reference_y = {1.0};
  for (std::size_t k = 0; k < curves.size(); ++k) {
    plot::LineSeries s;
    s.name = legend[k];
    s.colour = plot::series_colour(k);
    for (const GroundReactionRow& row : curves[k]) {
      s.x.push_back(row.trapdoor_displacement / widths[k]);
      s.y.push_back(row.trapdoor.ratio);
    }
    chart.series.push_back(std::move(s));
  }
  plot::write_line_chart(out, chart);
  return legend;
}

}  // namespace trapdem
