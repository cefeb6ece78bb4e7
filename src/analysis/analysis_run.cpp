#include "analysis/analysis_run.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

#include "analysis/delaunay.hpp"
#include "analysis/field_smoothing.hpp"
#include "io/lammps_dump.hpp"
#include "analysis/grid_interpolation.hpp"
#include "analysis/horizontal_profile.hpp"
#include "core/length_text.hpp"
#include "analysis/total_strain.hpp"
#include "core/errors.hpp"

namespace trapdem {

const char* view_name(ViewKind view) { return view == ViewKind::front ? "front" : "all"; }

namespace {

std::string list_displacements(const std::vector<double>& displacements) {
  std::string s;
  for (std::size_t k = 0; k < displacements.size(); ++k) {
    if (k) s += ", ";
    s += format_mm(displacements[k]);
  }
  return s;
}

std::size_t find_latest(const std::vector<double>& displacements, double target, double tolerance,
                        const char* option) {
  const double tol = std::max(tolerance, 0.02 * std::abs(target));
  for (std::size_t k = displacements.size(); k-- > 0;) {
    if (std::abs(displacements[k] - target) <= tol) return k;
  }
  throw InputError(fmt::format("{} {}: no snapshot at that trapdoor displacement (within {}); the snapshots are at {}",
                               option, format_mm(target), format_mm(tol), list_displacements(displacements)));
}

}  // namespace

FrameChoice choose_frames(const std::vector<double>& displacements, const AnalysisSettings& settings) {
  if (displacements.size() < 2) {
    throw InputError(fmt::format("the analysis needs at least two snapshots (a reference and a later one); found {}",
                                 displacements.size()));
  }
  FrameChoice choice;
  choice.reference = find_latest(displacements, settings.reference, settings.match_tolerance, "--reference");
  choice.at = std::isnan(settings.at) ? displacements.size() - 1
                                      : find_latest(displacements, settings.at, settings.match_tolerance, "--at");
  if (choice.at <= choice.reference) {
    throw InputError(fmt::format("--at {} must be a snapshot after the reference ({}); the snapshots are at {}",
                                 format_mm(displacements[choice.at]), format_mm(displacements[choice.reference]),
                                 list_displacements(displacements)));
  }
  if (settings.incremental) {
    for (std::size_t k = choice.reference + 1; k < choice.at; ++k) choice.between.push_back(k);
  }
  return choice;
}

double quantile(std::vector<double> values, double q) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double s = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(s);
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (s - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

namespace {

// For each frame after the reference: its ids missing from the reference, and the reference's ids
// missing from it, each with the first few ids (a particle left out of the analysis is named).
std::vector<std::string> unmatched_id_warnings(const std::vector<AnalysisFrame>& frames,
                                               const std::vector<std::unordered_map<std::int64_t, std::size_t>>& index) {
  const auto listed = [](const std::vector<std::int64_t>& ids) {
    constexpr std::size_t kShown = 5;
    std::string text;
    for (std::size_t i = 0; i < std::min(ids.size(), kShown); ++i) text += (i ? ", " : "") + std::to_string(ids[i]);
    return ids.size() > kShown ? text + ", ..." : text;
  };
  std::vector<std::string> warnings;
  const Snapshot& ref = frames.front().snapshot;
  for (std::size_t f = 1; f < frames.size(); ++f) {
    std::vector<std::int64_t> missing, unknown;
    for (std::size_t k = 0; k < ref.size(); ++k)
      if (!index[f].count(ref.id[k])) missing.push_back(ref.id[k]);
    for (const std::int64_t id : frames[f].snapshot.id)
      if (!index.front().count(id)) unknown.push_back(id);
    if (!missing.empty())
      warnings.push_back(fmt::format("{} particle{} of the reference {} {} missing from {} (id {}): left out of the "
                                     "analysis",
                                     missing.size(), missing.size() == 1 ? "" : "s", frames.front().label,
                                     missing.size() == 1 ? "is" : "are", frames[f].label, listed(missing)));
    if (!unknown.empty())
      warnings.push_back(fmt::format("{} particle{} of {} {} not in the reference {} (id {}): left out of the analysis",
                                     unknown.size(), unknown.size() == 1 ? "" : "s", frames[f].label,
                                     unknown.size() == 1 ? "is" : "are", frames.front().label, listed(unknown)));
  }
  return warnings;
}

}  // namespace

AnalysisResult analyze_frames(const std::vector<AnalysisFrame>& frames, const SpecimenGeometry& geometry,
                              AnalysisSettings settings) {
  if (frames.size() < 2) throw InputError("the analysis needs a reference and a current snapshot");
  if (!(geometry.trapdoor.width > 0.0)) throw InputError("the trapdoor width must be positive");
  AnalysisResult r;
  r.geometry = geometry;
  const Snapshot& ref = frames.front().snapshot;
  r.reference_label = frames.front().label;
  r.at_label = frames.back().label;
  r.reference_displacement = frames.front().trapdoor_displacement;
  r.at_displacement = frames.back().trapdoor_displacement;
  if (!(r.trapdoor_travel() > 0.0)) {
    throw InputError(fmt::format("the trapdoor moved {} between the reference ({}) and the current snapshot ({}): "
                                 "nothing to analyse",
                                 format_mm(r.trapdoor_travel()), r.reference_label, r.at_label));
  }

  // Index of every id in each frame (an id twice in one frame is refused: the particles could not
  // be followed); keep ids present in all, and say which are not.
  std::vector<std::unordered_map<std::int64_t, std::size_t>> index(frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Snapshot& s = frames[f].snapshot;
    index[f].reserve(s.size());
    for (std::size_t k = 0; k < s.size(); ++k)
      if (const auto [it, inserted] = index[f].emplace(s.id[k], k); !inserted)
        throw InputError(fmt::format("{}: particle id {} appears twice (particles {} and {}): the analysis follows "
                                     "each particle by its id, which must be unique",
                                     frames[f].label, s.id[k], it->second, k));
  }
  std::vector<std::size_t> matched;  // indices into the reference
  for (std::size_t k = 0; k < ref.size(); ++k) {
    bool everywhere = true;
    for (std::size_t f = 1; f < frames.size() && everywhere; ++f) everywhere = index[f].count(ref.id[k]) > 0;
    if (everywhere) matched.push_back(k);
  }
  r.unmatched_ids = unmatched_id_warnings(frames, index);
  r.matched_particles = matched.size();
  if (matched.size() < 3) {
    throw InputError(fmt::format("only {} particles appear in both {} and {} (matched by id)", matched.size(),
                                 r.reference_label, r.at_label));
  }
  for (std::size_t k : matched) r.max_diameter = std::max(r.max_diameter, 2.0 * ref.radius[k]);

  // The plane-strain view, chosen in the reference configuration.
  if (settings.front_depth <= 0.0) settings.front_depth = 1.5 * r.max_diameter;
  std::vector<std::size_t> viewed;
  for (std::size_t k : matched) {
    if (settings.view == ViewKind::all || geometry.box_depth - ref.position[k].y <= settings.front_depth) {
      viewed.push_back(k);
    }
  }
  if (viewed.size() < 3) {
    throw InputError(fmt::format("the {} view holds {} particles (front depth {}, box depth {})",
                                 view_name(settings.view), viewed.size(), format_mm(settings.front_depth),
                                 format_mm(geometry.box_depth)));
  }
  double diameter_sum = 0.0;
  std::vector<std::vector<Point2>> configurations(frames.size());
  for (std::size_t k : viewed) {
    r.id.push_back(ref.id[k]);
    r.radius.push_back(ref.radius[k]);
    diameter_sum += 2.0 * ref.radius[k];
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const std::size_t j = f == 0 ? k : index[f].at(ref.id[k]);
      const Vec3& p = frames[f].snapshot.position[j];
      configurations[f].push_back({p.x, p.z});
    }
  }
  r.mean_diameter = diameter_sum / static_cast<double>(viewed.size());
  r.points = point_set_between(configurations.front(), configurations.back());

  // Mesh and strain.
  settings.filter.mean_diameter = r.mean_diameter;
  const TriangleMesh delaunay = delaunay_triangulation(r.points.position);
  r.delaunay_triangles = delaunay.size();
  r.mesh = filter_triangles(delaunay, r.points.position, settings.filter);
  if (r.mesh.mesh.size() == 0) throw InputError("no triangle is left after filtering: too few particles in the view");
  r.strain = total_strains(r.mesh.mesh, r.points);
  r.gamma_max = maximum_shear_strains(r.strain);
  r.volumetric = volumetric_strains(r.strain);
  if (settings.incremental) {
    r.has_incremental = true;
    r.accumulated = accumulated_incremental_strain(r.mesh.mesh, configurations);
    r.gamma_max_incremental = r.accumulated.max_shear;
    r.volumetric_incremental = volumetric_strains(r.accumulated.strain);
  }

  // Grid of vertical displacement.
  if (settings.grid_spacing <= 0.0) settings.grid_spacing = 0.5 * r.mean_diameter;
  r.vertical_displacement = interpolate_nodal_field(r.mesh.mesh, r.points.position, vertical_displacements(r.points),
                                                    grid_covering(r.points.position, settings.grid_spacing));

  // Metrics.
  settings.bands.mean_diameter = r.mean_diameter;
  const TriangleField gamma_field = make_triangle_field(r.mesh.mesh, r.points.position, r.gamma_max);
  const TriangleField smoothed =
      smooth_triangle_field(gamma_field, settings.bands.smoothing_diameters * r.mean_diameter);
  r.gamma_max_smoothed = smoothed.value;
  r.bands = trace_shear_bands(gamma_field, smoothed, geometry.trapdoor, settings.bands);
  settings.zone.mean_diameter = r.mean_diameter;
  settings.zone.trapdoor_displacement = r.trapdoor_travel();
  r.zone = zone_of_influence(r.points, geometry.trapdoor, settings.zone);
  r.shape = classify_mechanism_shape(r.bands, r.zone);
  for (const double fraction : kZoneFractions) {
    ZoneOfInfluenceSettings at = settings.zone;
    at.settlement_fraction = fraction;
    r.zone_at_fractions.push_back(zone_of_influence(r.points, geometry.trapdoor, at));
  }
  // Beside the walls: the triangles whose centroid lies within B of the outermost particles.
  const std::vector<Point2> centroids = triangle_centroids(r.mesh.mesh, r.points.position);
  const std::vector<double> areas = triangle_areas(r.mesh.mesh, r.points.position);
  double left_sum = 0.0, left_area = 0.0, right_sum = 0.0, right_area = 0.0;
  const double B = geometry.trapdoor.width;
  for (std::size_t t = 0; t < centroids.size(); ++t) {
    if (!std::isfinite(r.volumetric[t])) continue;
    if (centroids[t].x <= r.zone.wall_left_x + B) {
      left_sum += r.volumetric[t] * areas[t];
      left_area += areas[t];
    } else if (centroids[t].x >= r.zone.wall_right_x - B) {
      right_sum += r.volumetric[t] * areas[t];
      right_area += areas[t];
    }
  }
  if (left_area > 0.0) r.volumetric_beside_left_wall = left_sum / left_area;
  if (right_area > 0.0) r.volumetric_beside_right_wall = right_sum / right_area;
  r.settings = settings;
  return r;
}

AnalysisResult analyze_snapshot_file(const std::filesystem::path& h5_path, const SpecimenGeometry& geometry,
                                     const AnalysisSettings& settings) {
  const auto infos = list_snapshots(h5_path);
  std::vector<double> displacements;
  for (const auto& info : infos) displacements.push_back(info.trapdoor_displacement);
  const FrameChoice choice = choose_frames(displacements, settings);
  std::vector<std::size_t> order{choice.reference};
  order.insert(order.end(), choice.between.begin(), choice.between.end());
  order.push_back(choice.at);
  std::vector<AnalysisFrame> frames;
  for (std::size_t k : order) {
    // A run of clumps is analysed on its grains' centres of mass, not on their member spheres.
    frames.push_back({infos[k].name, infos[k].trapdoor_displacement, grain_view(read_snapshot(h5_path, infos[k].name))});
  }
  return analyze_frames(frames, geometry, settings);
}

AnalysisResult analyze_dump_files(const std::vector<std::filesystem::path>& dumps,
                                  const std::vector<double>& displacements, const SpecimenGeometry& geometry,
                                  const AnalysisSettings& settings) {
  if (dumps.size() != displacements.size()) {
    throw InputError(fmt::format("{} dump files but {} displacements: give one trapdoor displacement per dump "
                                 "(--displacements 0mm,10mm,...)",
                                 dumps.size(), displacements.size()));
  }
  const FrameChoice choice = choose_frames(displacements, settings);
  std::vector<std::size_t> order{choice.reference};
  order.insert(order.end(), choice.between.begin(), choice.between.end());
  order.push_back(choice.at);
  std::vector<AnalysisFrame> frames;
  for (std::size_t k : order) {
    Snapshot s = read_dump_file(dumps[k]);
    s.trapdoor_displacement = displacements[k];
    frames.push_back({dumps[k].filename().string(), displacements[k], std::move(s)});
  }
  return analyze_frames(frames, geometry, settings);
}

}  // namespace trapdem
