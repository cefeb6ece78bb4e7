#include "study/stored_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "analysis/analysis_run.hpp"
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
