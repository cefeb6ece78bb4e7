#include "study/run_comparison.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/grid_interpolation.hpp"
#include "core/errors.hpp"
#include "core/length_text.hpp"
#include "experiment/run_folder.hpp"
#include "io/snapshot.hpp"
#include "plot/comparison_figure.hpp"
#include "study/run_analysis.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

std::size_t snapshot_index(const std::vector<SnapshotInfo>& infos, const std::string& name) {
  for (std::size_t k = 0; k < infos.size(); ++k) {
    if (infos[k].name == name) return k;
  }
  return infos.size();
}

// The PIV image (1-based) made from DEM snapshot `index` by `trapdem render`, or 0.
std::size_t image_of_snapshot(const std::vector<std::string>& names, std::size_t index) {
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (rendered_snapshot_index(names[k]) == static_cast<long>(index)) return k + 1;
  }
  return 0;
}

}  // namespace

std::string percent_text(double x) { return fmt::format("{:.2f} %", 100.0 * x); }

CompareResult compare_directories(const CompareOptions& o) {
  if (o.at.empty()) throw InputError("trapdem compare: give --at, the trapdoor displacement to compare (e.g. 10mm)");
  // The option values first: a mistyped --at or --grid is reported before any file is read.
  const double at = parse_length(o.at, "--at");
  const double spacing = parse_length(o.grid, "--grid");
  if (!(spacing > 0.0)) throw InputError("--grid must be positive");
  const RunFolder run(o.dem_dir);
  if (!fs::is_directory(run.path())) throw InputError(fmt::format("{}: no such run folder", run.path().string()));
  const SpecimenGeometry geometry = load_specimen_geometry(run.resolved_toml());
  const fs::path snapshots = run.snapshots_h5();
  if (!fs::exists(snapshots)) {
    throw InputError(fmt::format("{}: not found (run `trapdem run` first)", snapshots.string()));
  }
  fs::path piv_h5 = o.piv_dir;
  if (piv_h5.extension() != ".h5") piv_h5 /= "piv.h5";  // a PIV output folder

  // DEM: vertical displacement from the start of lowering (0 mm) to --at, front view.
  AnalysisSettings settings;
  settings.at = at;
  settings.reference = 0.0;
  settings.grid_spacing = spacing;
  const AnalysisResult dem = analyze_snapshot_file(snapshots, geometry, settings);

  CompareResult c;
  c.geometry = geometry;
  c.reference_displacement = dem.reference_displacement;
  c.at_displacement = dem.at_displacement;
  c.dem_reference_label = dem.reference_label;
  c.dem_at_label = dem.at_label;

  // PIV images: by name when the images were rendered from this run's snapshots, else given.
  const std::vector<std::string> names = piv_image_names(piv_h5);
  const auto infos = list_snapshots(snapshots);
  const std::size_t at_index = snapshot_index(infos, dem.at_label);
  const std::size_t ref_index = snapshot_index(infos, dem.reference_label);
  const std::size_t matched_image = image_of_snapshot(names, at_index);
  const std::size_t matched_reference = image_of_snapshot(names, ref_index);
  if (o.image > 0) {
    c.piv_image = o.image;
    c.image_choice = "--image";
  } else if (matched_image > 0) {
    c.piv_image = matched_image;
    c.image_choice = fmt::format("rendered from DEM snapshot {}", at_index);
  } else {
    throw InputError(fmt::format(
        "{}: no PIV image is named after DEM snapshot {} ({}; `trapdem render` names it {:03d}_...mm.png): give "
        "--image N (1 to {}) and, if image 1 is not the start of lowering, --reference-image M",
        piv_h5.string(), at_index, format_mm(dem.at_displacement), at_index, names.size()));
  }
  if (o.reference_image > 0) {
    c.piv_reference_image = o.reference_image;
    c.image_choice += ", --reference-image";
  } else if (matched_reference > 0 && (o.image == 0 || matched_image == o.image)) {
    c.piv_reference_image = matched_reference;
    c.image_choice += fmt::format("; reference rendered from DEM snapshot {}", ref_index);
  } else if (o.image == 0) {
    throw InputError(fmt::format("{}: no PIV image is named after DEM snapshot {}, the start of lowering (the "
                                 "reference): include it in the PIV sequence or give --reference-image M",
                                 piv_h5.string(), ref_index));
  } else {
    c.piv_reference_image = 1;
    c.image_choice += "; reference image 1";
  }
  c.piv_image_name = fs::path(names.at(std::min(c.piv_image, names.size()) - 1)).filename().string();
  c.piv_reference_name =
      fs::path(names.at(std::min(c.piv_reference_image, names.size()) - 1)).filename().string();

  Point2 origin{geometry.trapdoor.centre_x, geometry.trapdoor.base_z};
  if (!o.piv_trapdoor.empty()) {
    const auto v = parse_length_list(o.piv_trapdoor, "--piv-trapdoor");
    if (v.size() != 2) throw InputError("--piv-trapdoor: expected X,Z (e.g. 125mm,0mm)");
    origin = {v[0], v[1]};
  }
  ScatteredDisplacement piv = read_piv_vertical_displacement(piv_h5, c.piv_reference_image, c.piv_image, origin);

  // Both in trapdoor coordinates on the grid over the area both cover.
  const Point2 centre{geometry.trapdoor.centre_x, geometry.trapdoor.base_z};
  std::vector<Point2> dem_nodes;
  dem_nodes.reserve(dem.points.size());
  for (const Point2& p : dem.points.position) dem_nodes.push_back(p - centre);
  const GridSpec grid = common_grid(dem_nodes, piv.position, spacing);
  c.dem = interpolate_nodal_field(dem.mesh.mesh, dem_nodes, vertical_displacements(dem.points), grid);
  c.piv = interpolate_scattered(piv, grid);
  c.error = compare_fields(c.dem, c.piv, c.trapdoor_travel());
  return c;
}

void write_compare_figure(CompareResult c, const fs::path& out) {
  const double delta = c.trapdoor_travel();
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  plot::ComparisonFigure fig;
  fig.title = fmt::format("{}: DEM against PIV, settlement at δ = {}", c.geometry.name, format_mm(delta));
  fig.subtitle = fmt::format(
      "RMS(w_DEM - w_PIV) / δ = {} over the compared area; bias {}; {} of the grid compared\n"
      "PIV image {} ({}) from image {} ({}); grid {}; DEM snapshots {} -> {}",
      percent_text(c.error.rms_normalised()), percent_text(c.error.bias_normalised()), percent_text(c.error.coverage), c.piv_image,
      c.piv_image_name, c.piv_reference_image, c.piv_reference_name, format_mm(c.dem.grid.spacing),
      c.dem_reference_label, c.dem_at_label);
  mask_to_common(c.dem, c.piv);
  fig.dem = c.dem;
  fig.piv = c.piv;
  const TrapdoorGeometry& t = c.geometry.trapdoor;
  fig.box_left = -t.centre_x;
  fig.box_right = c.geometry.box_width - t.centre_x;
  fig.box_height = c.geometry.box_height - t.base_z;
  fig.trapdoor_width = t.width;
  fig.trapdoor_travel = delta;
  plot::write_comparison_figure(out, fig);
}

fs::path default_compare_figure(const CompareOptions& o, const CompareResult& c) {
  return RunFolder(o.dem_dir).analysis().compare_png(c.at_displacement);
}

}  // namespace trapdem
