#pragma once
// The whole-run analysis behind `trapdem analyze`: from particle snapshots (trapdem's
// snapshots.h5 or LAMMPS/LIGGGHTS text dumps) to strain fields, the vertical displacement grid,
// the shear-band metrics and the zone of influence.
//
// Steps: choose the reference and current snapshots by trapdoor displacement; match particles by
// id; keep the plane-strain view (particles within front_depth of the front window y = depth, or
// all), chosen in the reference snapshot; project on the x-z plane; Delaunay-triangulate the
// reference centres; filter; total strain (reference -> current) and, optionally, accumulated
// incremental strain over every snapshot between; vertical displacement on a grid; metrics.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "analysis/grid_field.hpp"
#include "analysis/incremental_strain.hpp"
#include "analysis/mechanism_shape.hpp"
#include "analysis/point_set.hpp"
#include "analysis/shear_bands.hpp"
#include "analysis/trapdoor_geometry.hpp"
#include "analysis/triangle_filter.hpp"
#include "analysis/zone_of_influence.hpp"
#include "io/snapshot.hpp"

namespace trapdem {

enum class ViewKind { front, all };
const char* view_name(ViewKind view);

// Where things are: from the run's resolved.toml (box and trapdoor sections).
struct SpecimenGeometry {
  std::string name = "trapdoor";  // the case, for titles
  double box_width = 0.0;         // m (x)
  double box_depth = 0.0;         // m (y); the front window is at y = box_depth
  double box_height = 0.0;        // m (z)
  TrapdoorGeometry trapdoor;      // base_z = 0
};

struct AnalysisSettings {
  double at = std::numeric_limits<double>::quiet_NaN();  // m of trapdoor travel; NaN: the last snapshot
  double reference = 0.0;                                // m
  ViewKind view = ViewKind::front;
  double front_depth = 0.0;     // m; 0: 1.5 largest particle diameters
  bool incremental = false;     // also accumulate incremental strain over the snapshots between
  double grid_spacing = 0.0;    // m; 0: half the mean diameter
  // Matching a requested displacement: within max(match_tolerance, 2 % of it).
  double match_tolerance = 5e-5;
  TriangleFilterSettings filter;           // mean_diameter is filled in from the particles
  ShearBandSettings bands;                 // mean_diameter filled in
  ZoneOfInfluenceSettings zone;            // mean_diameter and trapdoor_displacement filled in
};

// One snapshot as the analysis sees it.
struct AnalysisFrame {
  std::string label;  // snapshot group name or dump file name
  double trapdoor_displacement = 0.0;  // m
  Snapshot snapshot;
};

// Indices into a series of trapdoor displacements: the reference, the current one and (when
// `incremental`) every index strictly between them. For a requested displacement the latest
// snapshot within tolerance is taken (the start of lowering, not the pluviation, for 0 mm).
// Throws InputError listing the available displacements if one is not found, or if the current
// snapshot does not come after the reference.
struct FrameChoice {
  std::size_t reference = 0;
  std::size_t at = 0;
  std::vector<std::size_t> between;
};
FrameChoice choose_frames(const std::vector<double>& displacements, const AnalysisSettings& settings);

struct AnalysisResult {
  SpecimenGeometry geometry;
  AnalysisSettings settings;           // as used: front_depth, grid_spacing and diameters resolved
  std::string reference_label, at_label;
  double reference_displacement = 0.0;  // m, trapdoor travel of the reference snapshot
  double at_displacement = 0.0;         // m, of the current snapshot
  double trapdoor_travel() const { return at_displacement - reference_displacement; }

  std::size_t matched_particles = 0;  // in every snapshot used
  // Particles left out because their id is not in every snapshot used: what is missing where,
  // with the first ids (metrics.json `warnings`, the terminal); empty when all match.
  std::vector<std::string> unmatched_ids;
  double mean_diameter = 0.0;         // m, of the viewed particles
  double max_diameter = 0.0;          // m, of all matched particles

  // The viewed particles, node k in each.
  std::vector<std::int64_t> id;
  std::vector<double> radius;  // m
  PointSet2 points;            // reference x-z centres and displacement to the current snapshot

  std::size_t delaunay_triangles = 0;
  FilteredMesh mesh;                       // kept triangles and drop counts
  std::vector<PlaneStrain> strain;         // total, per kept triangle
  std::vector<double> gamma_max;           // total maximum shear strain
  std::vector<double> volumetric;          // total volumetric strain (compression positive)

  bool has_incremental = false;
  AccumulatedStrain accumulated;           // per kept triangle
  std::vector<double> gamma_max_incremental;  // accumulated incremental gamma_max (cumulative shear)
  std::vector<double> volumetric_incremental; // volumetric strain of the accumulated components

  GridField vertical_displacement;  // m, w on a regular grid over the reference centres
  // gamma_max smoothed at settings.bands.smoothing_diameters (field_smoothing.hpp): the field the
  // bands are traced on and the smoothed strain figure shows; equal to gamma_max when 0.
  std::vector<double> gamma_max_smoothed;
  ShearBandPair bands;
  ZoneOfInfluence zone;
  MechanismShapeResult shape;  // columnar or elliptical, from the bands or the zone's width
  // The zone at higher thresholds (10, 25 and 50 % of the travel): how its width depends on the
  // threshold (a referee's first question of a 5 % zone; issue 36).
  std::vector<ZoneOfInfluence> zone_at_fractions;
  // The far field: the mean volumetric strain (area-weighted, compression positive) of the kept
  // triangles within one trapdoor width of each side wall's outermost particles: near zero when
  // only the mechanism over the door moves, not when the whole deposit compacts.
  double volumetric_beside_left_wall = std::numeric_limits<double>::quiet_NaN();
  double volumetric_beside_right_wall = std::numeric_limits<double>::quiet_NaN();
};

// The thresholds of AnalysisResult::zone_at_fractions.
inline constexpr double kZoneFractions[] = {0.10, 0.25, 0.50};

// The analysis of a sequence of frames: frames[0] the reference, frames.back() the current one,
// any in between used for the incremental strain (when settings.incremental).
AnalysisResult analyze_frames(const std::vector<AnalysisFrame>& frames, const SpecimenGeometry& geometry,
                              AnalysisSettings settings);

// Reads the snapshots the settings call for from snapshots.h5 and analyses them.
AnalysisResult analyze_snapshot_file(const std::filesystem::path& h5_path, const SpecimenGeometry& geometry,
                                     const AnalysisSettings& settings);

// The same for text dumps, one per snapshot, with the trapdoor displacement of each (m).
AnalysisResult analyze_dump_files(const std::vector<std::filesystem::path>& dumps,
                                  const std::vector<double>& displacements, const SpecimenGeometry& geometry,
                                  const AnalysisSettings& settings);

// Quantile q in [0, 1] of the finite values (linear between order statistics); NaN if none.
double quantile(std::vector<double> values, double q);

}  // namespace trapdem
