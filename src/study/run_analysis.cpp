#include "study/run_analysis.hpp"

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
#include "core/errors.hpp"
#include "core/length_text.hpp"
#include "experiment/ground_reaction.hpp"
#include "experiment/run_folder.hpp"
#include "io/lammps_dump.hpp"
#include "io/text_file.hpp"
#include "plot/figure_format.hpp"
#include "plot/line_chart.hpp"
#include "plot/specimen_figures.hpp"

namespace fs = std::filesystem;

namespace trapdem {

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

plot::ContourLevels contour_levels_option(const std::string& levels, const std::string& step) {
  plot::ContourLevels c;
  if (!levels.empty() && !step.empty()) throw InputError("--contour-levels and --contour-step exclude each other");
  if (!levels.empty()) c.list = parse_length_list(levels, "--contour-levels");
  if (!step.empty()) {
    c.step = parse_length(step, "--contour-step");
    if (!(c.step > 0.0)) throw InputError(fmt::format("--contour-step '{}': must be positive", step));
  }
  return c;
}

SpecimenGeometry specimen_geometry(const ExperimentConfig& e) {
  SpecimenGeometry g;
  g.name = e.name;
  g.box_width = e.box.width;
  g.box_depth = e.box.depth;
  g.box_height = e.box.height;
  g.trapdoor = {e.trapdoor.centre, e.trapdoor.width, 0.0};
  return g;
}

SpecimenGeometry load_specimen_geometry(const fs::path& config_file) {
  return specimen_geometry(RunFolder::read_specimen(
      config_file, "the analysis needs the box and trapdoor geometry (a run folder's resolved.toml, or --config FILE "
                   "with [box] and [trapdoor])"));
}

namespace {

// DIR/snapshots.h5, checked to exist; --displacements without --dumps refused.
fs::path snapshot_file(const AnalyzeOptions& o) {
  if (!o.displacements.empty()) throw InputError("--displacements goes with --dumps");
  const fs::path h5 = RunFolder(o.dir).snapshots_h5();
  if (!fs::exists(h5)) {
    throw InputError(fmt::format("{}: not found (run `trapdem run` first, or give --dumps FILE...)", h5.string()));
  }
  return h5;
}

// --field-history-grid (m; 0: the default, one mean diameter), checked against the box: a positive
// length whose grid over the box fits check_grid_memory.
double field_history_spacing(const AnalyzeOptions& o, const SpecimenGeometry& geometry) {
  if (o.field_history_grid.empty()) return 0.0;
  const double spacing = parse_length(o.field_history_grid, "--field-history-grid");
  if (!(spacing > 0.0))
    throw InputError(fmt::format("--field-history-grid {}: expected a positive length", o.field_history_grid));
  check_grid_memory(geometry.box_width, geometry.box_height, spacing, "--field-history-grid");
  return spacing;
}

}  // namespace

AnalysisResult analyze_directory(const AnalyzeOptions& o) {
  const RunFolder run(o.dir);
  const SpecimenGeometry geometry = load_specimen_geometry(o.config.empty() ? run.resolved_toml() : fs::path(o.config));
  const AnalysisSettings settings = analysis_settings(o);
  if (!o.dumps.empty()) {
    std::vector<fs::path> dumps(o.dumps.begin(), o.dumps.end());
    return analyze_dump_files(dumps, parse_length_list(o.displacements, "--displacements"), geometry, settings);
  }
  return analyze_snapshot_file(snapshot_file(o), geometry, settings);
}

FieldHistory field_history_of_directory(const AnalyzeOptions& o) {
  const RunFolder run(o.dir);
  const SpecimenGeometry geometry = load_specimen_geometry(o.config.empty() ? run.resolved_toml() : fs::path(o.config));
  const AnalysisSettings settings = analysis_settings(o);
  const double spacing = field_history_spacing(o, geometry);
  if (!o.dumps.empty()) {
    const std::vector<double> displacements = parse_length_list(o.displacements, "--displacements");
    if (displacements.size() != o.dumps.size())
      throw InputError(fmt::format("{} dump files but {} displacements: give one trapdoor displacement per dump",
                                   o.dumps.size(), displacements.size()));
    const FrameLoader load = [&](std::size_t k) {
      Snapshot s = read_dump_file(o.dumps[k]);
      s.trapdoor_displacement = displacements[k];
      return AnalysisFrame{fs::path(o.dumps[k]).filename().string(), displacements[k], std::move(s)};
    };
    return field_history(displacements, load, geometry, settings, spacing);
  }
  return field_history_of_snapshot_file(snapshot_file(o), geometry, settings, spacing);
}

fs::path analysis_output_dir(const AnalyzeOptions& o) {
  return o.out.empty() ? RunFolder(o.dir).analysis_dir() : fs::path(o.out);
}

namespace {

void write_ground_reaction_figure(const fs::path& csv, const fs::path& figure, const SpecimenGeometry& g) {
  const auto rows = parse_ground_reaction_csv(read_text_file(csv), csv.string());
  plot::LineChart chart;
  chart.title = fmt::format("{}: ground reaction curve", g.name);
  const double geostatic = rows.empty() ? 0.0 : rows.front().geostatic_stress;
  chart.subtitle = fmt::format("stress σ over its value before lowering σ0 (trapdoor: {:.3g} kPa); B = {}", geostatic / 1e3,
                               format_mm(g.trapdoor.width));
  chart.x_label = "trapdoor displacement δ/B (-)";
  chart.y_label = "stress ratio σ/σ0 (-)";
  chart.reference_y = {1.0};
  auto series = [](const char* name, plot::Rgb colour, bool dashed, double width) {
    plot::LineSeries s;
    s.name = name;
    s.colour = colour;
    s.dashed = dashed;
    s.width = width;
    return s;
  };
  plot::LineSeries trapdoor = series("trapdoor", {0.80, 0.10, 0.10}, false, 2.4);
  plot::LineSeries left = series("base, left", {0.13, 0.40, 0.67}, true, 2.0);
  plot::LineSeries right = series("base, right", {0.20, 0.60, 0.30}, true, 2.0);
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
  plot::write_line_chart(figure, chart);
}

}  // namespace

AnalysisResult analyze_and_write(const AnalyzeOptions& o, std::vector<fs::path>* written_files) {
  // The figure options are checked before the analysis runs.
  const plot::FigureFormat format = plot::parse_figure_format(o.format, "--format");
  const plot::ContourLevels levels = contour_levels_option(o.contour_levels, o.contour_step);
  if (!o.no_field_history) {
    const RunFolder run(o.dir);
    field_history_spacing(o, load_specimen_geometry(o.config.empty() ? run.resolved_toml() : fs::path(o.config)));
  }
  AnalysisResult r = analyze_directory(o);
  const AnalysisFolder out(analysis_output_dir(o));
  write_fields(out.fields_h5(), out.fields_xmf(), r);
  write_metrics(out.metrics_json(), r);
  std::vector<fs::path> written{out.fields_h5(), out.fields_xmf(), out.metrics_json()};
  if (!o.no_field_history) {
    write_field_history(out.field_history_h5(), field_history_of_directory(o));
    written.push_back(out.field_history_h5());
  }
  if (!o.no_figures) {
    const auto figure = [&](const fs::path& png) {
      written.push_back(plot::with_format(png, format));
      return written.back();
    };
    plot::write_strain_map(figure(out.shear_strain_png()), r, plot::StrainKind::total);
    plot::write_volumetric_strain_map(figure(out.volumetric_strain_png()), r);
    if (r.has_incremental) {
      plot::write_strain_map(figure(out.shear_strain_incremental_png()), r, plot::StrainKind::incremental);
    }
    plot::write_displacement_contours(figure(out.vertical_displacement_png()), r, levels);
    plot::write_particles_figure(figure(out.particles_png()), r);
    const fs::path csv = RunFolder(o.dir).trapdoor_csv();
    if (fs::exists(csv)) write_ground_reaction_figure(csv, figure(out.ground_reaction_png()), r.geometry);
  }
  if (written_files) *written_files = written;
  return r;
}

}  // namespace trapdem
