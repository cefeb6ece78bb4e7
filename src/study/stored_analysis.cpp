#include "study/stored_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "analysis/analysis_run.hpp"
#include "analysis/field_history.hpp"
#include "analysis/field_smoothing.hpp"
#include "analysis/hole_fill.hpp"
#include "core/errors.hpp"
#include "core/length_text.hpp"
#include "core/path_text.hpp"
#include "io/text_file.hpp"
#include "plot/figure_format.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

bool same_length(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b)); }

// What differs from the analysis the study makes (the defaults of AnalyzeOptions at the last
// snapshot), as "key (value)", or empty.
std::string differing_input(const Json& m, double end_of_lowering) {
  const Json& inputs = json_member_or_null(m, "inputs");
  const Json& particles = json_member_or_null(m, "particles");
  const AnalysisSettings defaults;
  if (!json_member_or_null(inputs, "at_requested_m").is_null())
    return fmt::format("inputs.at_requested_m ({}; the report analyses the last snapshot)",
                       json_number_or_nan(inputs, "at_requested_m"));
  if (json_number_or_nan(inputs, "reference_requested_m") != defaults.reference)
    return fmt::format("inputs.reference_requested_m ({}; the report's reference is the start of lowering)",
                       json_number_or_nan(inputs, "reference_requested_m"));
  const Json& view = json_member_or_null(inputs, "view");
  if (view.type() != Json::Type::string || view.as_string() != view_name(defaults.view))
    return fmt::format("inputs.view (expected \"{}\")", view_name(defaults.view));
  const Json& incremental = json_member_or_null(inputs, "incremental");
  if (incremental.type() != Json::Type::boolean || incremental.as_bool() != defaults.incremental)
    return "inputs.incremental (expected false)";
  // The defaults that depend on the particles (analysis_run.cpp): 1.5 largest and half the mean diameter.
  if (!same_length(json_number_or_nan(inputs, "front_depth_m"), 1.5 * json_number_or_nan(particles, "max_diameter_m")))
    return "inputs.front_depth_m (not the default 1.5 largest diameters)";
  if (!same_length(json_number_or_nan(inputs, "grid_spacing_m"), 0.5 * json_number_or_nan(particles, "mean_diameter_m")))
    return "inputs.grid_spacing_m (not the default half mean diameter)";
  if (json_number_or_nan(json_member_or_null(m, "shear_bands"), "smoothing_diameters") !=
      defaults.bands.smoothing_diameters)
    return fmt::format("shear_bands.smoothing_diameters (expected the default {:g})", defaults.bands.smoothing_diameters);
  // The last snapshot of a finished run is at the end of lowering; a metrics.json written while the
  // run was still going (then resumed) is of an earlier displacement. Same tolerance as the
  // analysis' matching of a requested displacement.
  const double at = json_number_or_nan(inputs, "at_m");
  const double tolerance = std::max(defaults.match_tolerance, 0.02 * end_of_lowering);
  if (!(std::fabs(at - end_of_lowering) <= tolerance))
    return fmt::format("inputs.at_m ({}; the run ends at {})", format_mm(at), format_mm(end_of_lowering));
  return "";
}

// A figure `trapdem analyze` drew, named by its PNG path: the PNG, else the SVG (what a page shows;
// a PDF is not shown as an image), else empty.
fs::path kept_figure(const fs::path& png) {
  for (const plot::FigureFormat format : {plot::FigureFormat::png, plot::FigureFormat::svg}) {
    const fs::path file = plot::with_format(png, format);
    if (fs::is_regular_file(file)) return file;
  }
  return {};
}

std::vector<BandTracePoint> trace_of(const Json& trace) {
  std::vector<BandTracePoint> points;
  const Json &z = json_member_or_null(trace, "z_m"), &x = json_member_or_null(trace, "x_m");
  if (z.type() != Json::Type::array || x.type() != Json::Type::array || z.size() != x.size()) return points;
  for (std::size_t k = 0; k < z.size(); ++k) {
    BandTracePoint p;
    p.z = z[k].as_number();
    p.x = x[k].as_number();
    if (std::isfinite(p.z) && std::isfinite(p.x)) points.push_back(p);
  }
  return points;
}

// The map of the last layer of the run's field_history.h5, if that layer is the analysis the
// metrics are of (the same snapshot, reference and view); else nothing and `why_not`.
std::optional<plot::StoredStrainMap> stored_strain_map(const RunFolder& run, const Json& m, const ExperimentConfig& specimen,
                                                       const std::string& file_name, std::string& why_not) {
  const fs::path file = run.analysis().field_history_h5();
  if (!fs::exists(file)) {
    why_not = fmt::format("{} is missing", file_name);
    return std::nullopt;
  }
  try {
    FieldHistory h = read_field_history(file);
    const Json& inputs = json_member_or_null(m, "inputs");
    const auto text = [&](const char* key) {
      const Json& v = json_member_or_null(inputs, key);
      return v.type() == Json::Type::string ? v.as_string() : std::string();
    };
    if (h.layers() == 0 || h.labels.back() != text("at_snapshot") || h.reference_label != text("reference_snapshot") ||
        h.view != text("view")) {
      why_not = fmt::format("{} is of another analysis than metrics.json (its last layer, snapshot {} from {}, {} "
                            "view; metrics.json: snapshot {} from {}, {} view)",
                            file_name, h.layers() ? h.labels.back() : "none", h.reference_label, h.view,
                            text("at_snapshot"), text("reference_snapshot"), text("view"));
      return std::nullopt;
    }
    plot::StoredStrainMap map;
    map.name = h.case_name;
    map.gamma_max.grid = h.grid;
    const std::size_t nodes = h.grid.nx * h.grid.nz, last = h.layers() - 1;
    map.gamma_max.value.assign(h.gamma_max.value.begin() + static_cast<std::ptrdiff_t>(last * nodes),
                               h.gamma_max.value.begin() + static_cast<std::ptrdiff_t>((last + 1) * nodes));
    const Json& bands = json_member_or_null(m, "shear_bands");
    const Json& trapdoor = json_member_or_null(m, "trapdoor");
    map.mean_diameter = json_number_or_nan(json_member_or_null(m, "particles"), "mean_diameter_m");
    map.smoothing_diameters = json_number_or_nan(bands, "smoothing_diameters");
    const double smoothing = json_number_or_nan(bands, "smoothing_m");
    map.trapdoor.centre_x = json_number_or_nan(trapdoor, "centre_x_m");
    map.trapdoor.width = json_number_or_nan(trapdoor, "width_m");
    map.travel = json_number_or_nan(trapdoor, "travel_m");
    map.box_width = specimen.box.width;
    for (const double v : {map.mean_diameter, map.smoothing_diameters, smoothing, map.trapdoor.centre_x,
                           map.trapdoor.width, map.travel})
      if (!std::isfinite(v)) {
        why_not = "metrics.json lacks the trapdoor's geometry, the particles' mean diameter or the smoothing length";
        return std::nullopt;
      }
    // Smoothed as the analysis smoothed the triangles; the nodes inside the specimen that no kept
    // triangle covered filled from their neighbours, as the analysis's figures fill their dropped
    // triangles (no white specks; empty space stays empty).
    map.gamma_max = fill_interior_grid_holes(smooth_grid_field(map.gamma_max, smoothing), 0.0, specimen.box.width);
    for (const char* side : {"left", "right"}) {
      const Json& band = json_member_or_null(bands, side);
      map.band_traces.push_back(trace_of(json_member_or_null(band, "trace")));
      const Json& branches = json_member_or_null(band, "branches");
      if (branches.type() == Json::Type::array)
        for (std::size_t k = 0; k < branches.size(); ++k)
          map.branch_traces.push_back(trace_of(json_member_or_null(branches[k], "trace")));
    }
    return map;
  } catch (const std::runtime_error& e) {  // InputError, FileError: a damaged or foreign file
    why_not = fmt::format("{} cannot be read: {}", file_name, e.what());
    return std::nullopt;
  }
}

}  // namespace

StoredAnalysis stored_final_analysis(const RunFolder& run, const fs::path& names_relative_to) {
  StoredAnalysis s;
  const fs::path file = run.metrics_json();
  const std::string file_name = path_from(file, names_relative_to);
  if (!fs::exists(file)) {
    s.note = fmt::format("not analysed: {} is missing and so is {}", run.snapshots_h5().filename().string(),
                         file_name);
    return s;
  }
  try {
    const ExperimentConfig specimen = run.specimen("the report checks the stored analysis against the run's travel");
    Json m = Json::parse(read_text_file(file), file.string());
    const std::string differs = differing_input(m, specimen.trapdoor.travel);
    if (!differs.empty()) {
      s.note = fmt::format("not analysed: {} is missing, and {} is another analysis than the report's: {}; run "
                           "`trapdem analyze` while the snapshots are there",
                           run.snapshots_h5().filename().string(), file_name, differs);
      return s;
    }
    s.strain_map = stored_strain_map(run, m, specimen, path_from(run.analysis().field_history_h5(), names_relative_to),
                                     s.strain_map_note);
    s.metrics = std::move(m);
  } catch (const InputError& e) {
    s.note = fmt::format("not analysed: {} is missing and {} cannot be read: {}", run.snapshots_h5().filename().string(),
                         file_name, e.what());
    return s;
  }
  s.strain_figure = kept_figure(run.analysis().shear_strain_png());
  s.displacement_figure = kept_figure(run.analysis().vertical_displacement_png());
  if (s.strain_figure.empty() && s.displacement_figure.empty()) {
    s.note = fmt::format("no figures: {} is gone; the numbers are from {}", run.snapshots_h5().filename().string(),
                         file_name);
  } else {
    s.note = fmt::format("{} is gone; the numbers are from {}, the figures are the run's own from {}",
                         run.snapshots_h5().filename().string(), file_name, path_from(file.parent_path(), names_relative_to));
  }
  return s;
}

}  // namespace trapdem
