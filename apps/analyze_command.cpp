#include "analyze_command.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "analysis/analysis_output.hpp"
#include "analysis/length_text.hpp"
#include "dem/errors.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/ground_reaction.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"
#include "plot/line_chart.hpp"
#include "plot/specimen_figures.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

std::vector<double> parse_length_list(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    if (item.find_first_not_of(" \t") != std::string::npos) out.push_back(parse_length(item, what));
    start = end + 1;
  }
  return out;
}

AnalysisSettings analysis_settings(const AnalyzeOptions& o) {
  AnalysisSettings s;
  if (!o.at.empty()) s.at = parse_length(o.at, "--at");
  s.reference = parse_length(o.reference, "--reference");
  if (o.view == "front") s.view = ViewKind::front;
  else if (o.view == "all") s.view = ViewKind::all;
  else throw InputError(fmt::format("--view '{}': expected front or all", o.view));
  if (!o.front_depth.empty()) {
    s.front_depth = parse_length(o.front_depth, "--front-depth");
    if (!(s.front_depth > 0.0)) throw InputError("--front-depth must be positive");
  }
  if (!o.grid.empty()) {
    s.grid_spacing = parse_length(o.grid, "--grid");
    if (!(s.grid_spacing > 0.0)) throw InputError("--grid must be positive");
  }
  s.bands.smoothing_diameters = o.smoothing;
  s.incremental = o.incremental;
  return s;
}

SpecimenGeometry load_specimen_geometry(const fs::path& config_file) {
  if (!fs::exists(config_file)) {
    throw InputError(fmt::format("{}: not found; the analysis needs the box and trapdoor geometry (a run folder's "
                                 "resolved.toml, or --config FILE with [box] and [trapdoor])",
                                 config_file.string()));
  }
  // Only the geometry is read (with the experiment's defaults), so a short file with [box] and
  // [trapdoor] describes a run made with another code; other keys are ignored.
  Config config = Config::load_file(config_file.string());
  const ExperimentConfig defaults;
  SpecimenGeometry g;
  g.name = config.get_string("name", defaults.name);
  g.box_width = config.get_double("box.width", defaults.box.width, "m", Range::positive());
  g.box_depth = config.get_double("box.depth", defaults.box.depth, "m", Range::positive());
  g.box_height = config.get_double("box.height", defaults.box.height, "m", Range::positive());
  const double width = config.get_double("trapdoor.width", defaults.trapdoor.width, "m", Range::positive());
  const double centre = config.get_double("trapdoor.centre", 0.5 * g.box_width, "m", Range::closed(0.0, g.box_width));
  g.trapdoor = {centre, width, 0.0};
  return g;
}

AnalysisResult analyze_directory(const AnalyzeOptions& o) {
  const fs::path dir = o.dir;
  const SpecimenGeometry geometry = load_specimen_geometry(o.config.empty() ? dir / "resolved.toml" : fs::path(o.config));
  const AnalysisSettings settings = analysis_settings(o);
  if (!o.dumps.empty()) {
    std::vector<fs::path> dumps(o.dumps.begin(), o.dumps.end());
    return analyze_dump_files(dumps, parse_length_list(o.displacements, "--displacements"), geometry, settings);
  }
  if (!o.displacements.empty()) throw InputError("--displacements goes with --dumps");
  const fs::path h5 = dir / "snapshots.h5";
  if (!fs::exists(h5)) {
    throw InputError(fmt::format("{}: not found (run `trapdem run` first, or give --dumps FILE...)", h5.string()));
  }
  return analyze_snapshot_file(h5, geometry, settings);
}

namespace {

void write_ground_reaction_figure(const fs::path& csv, const fs::path& png, const SpecimenGeometry& g) {
  const auto rows = parse_ground_reaction_csv(read_text_file(csv), csv.string());
  plot::LineChart chart;
  chart.title = fmt::format("{}: ground reaction curve", g.name);
  const double geostatic = rows.empty() ? 0.0 : rows.front().geostatic_stress;
  chart.subtitle = fmt::format("stress over its value before lowering (trapdoor: {:.3g} kPa); B = {}", geostatic / 1e3,
                               format_mm(g.trapdoor.width));
  chart.x_label = "trapdoor displacement / trapdoor width  δ/B (-)";
  chart.y_label = "stress / stress before lowering (-)";
  chart.reference_y = {1.0};
  auto series = [](const char* name, plot::Rgb colour, bool dashed, double width) {
    plot::LineSeries s;
    s.name = name;
    s.colour = colour;
    s.dashed = dashed;
    s.width = width;
    return s;
  };
  plot::LineSeries trapdoor = series("trapdoor", {0.80, 0.10, 0.10}, false, 3.0);
  plot::LineSeries left = series("base, left", {0.13, 0.40, 0.67}, true, 2.5);
  plot::LineSeries right = series("base, right", {0.20, 0.60, 0.30}, true, 2.5);
  for (const auto& row : rows) {
    const double x = row.trapdoor_displacement / g.trapdoor.width;
    trapdoor.x.push_back(x);
    trapdoor.y.push_back(row.trapdoor.ratio);
    left.x.push_back(x);
    left.y.push_back(row.base_left.ratio);
    right.x.push_back(x);
    right.y.push_back(row.base_right.ratio);
  }
  chart.series = {trapdoor, left, right};
  plot::write_line_chart_png(png, chart);
}

}  // namespace

AnalysisResult analyze_and_write(const AnalyzeOptions& o, std::vector<fs::path>* written_files) {
  AnalysisResult r = analyze_directory(o);
  const fs::path out = o.out.empty() ? fs::path(o.dir) / "analysis" : fs::path(o.out);
  write_fields(out, r);
  write_metrics(out, r);
  std::vector<fs::path> written{out / "fields.h5", out / "fields.xmf", out / "metrics.json"};
  if (!o.no_figures) {
    plot::write_strain_map_png(out / "shear_strain.png", r, plot::StrainKind::total);
    written.push_back(out / "shear_strain.png");
    if (r.has_incremental) {
      plot::write_strain_map_png(out / "shear_strain_incremental.png", r, plot::StrainKind::incremental);
      written.push_back(out / "shear_strain_incremental.png");
    }
    plot::write_displacement_contours_png(out / "vertical_displacement.png", r);
    written.push_back(out / "vertical_displacement.png");
    plot::write_particles_png(out / "particles.png", r);
    written.push_back(out / "particles.png");
    const fs::path csv = fs::path(o.dir) / "trapdoor.csv";
    if (fs::exists(csv)) {
      write_ground_reaction_figure(csv, out / "ground_reaction.png", r.geometry);
      written.push_back(out / "ground_reaction.png");
    }
  }
  if (written_files) *written_files = written;
  return r;
}

int run_analyze(const AnalyzeOptions& o) {
  std::vector<fs::path> written;
  const AnalysisResult r = analyze_and_write(o, &written);
  const fs::path out = o.out.empty() ? fs::path(o.dir) / "analysis" : fs::path(o.out);
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
