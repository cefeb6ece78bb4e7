#pragma once
// The mechanism at every snapshot of the lowering on one regular grid: settlement, maximum shear
// strain and volumetric strain, float32 and compressed, a few MB for a paper-scale case. It is what
// a later analysis needs once the snapshots (GB) are gone: contours at any travel, widths at other
// thresholds, strain percentiles, the fields of two runs subtracted (issue 36).
//
// Each snapshot after the reference is analysed against the reference exactly as `trapdem analyze
// --at` analyses it (same view, matching, Delaunay mesh and triangle filter; total strain, not the
// incremental one), and its fields are sampled on one grid that covers the reference centres:
// the vertical displacement linearly inside each kept triangle, gamma_max and the volumetric
// strain constant in each (the triangle's constant-strain value, unsmoothed), NaN where no kept
// triangle covers a node. Layout of the file: docs/analysis.md, "field_history.h5".
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "analysis/grid_field.hpp"
#include "io/hdf5_file.hpp"

namespace trapdem {

struct FieldHistory {
  std::string case_name;
  std::string view;                  // front | all
  double front_depth = 0.0;          // m
  double mean_diameter = 0.0;        // m, of the viewed particles (reference analysis)
  GridSpec grid;                     // one for every layer; node (i, j) at (grid.x(i), grid.z(j))
  std::string reference_label;
  double reference_displacement = 0.0;  // m, trapdoor travel of the reference snapshot
  // One layer per snapshot after the reference, in order of the snapshots.
  std::vector<std::string> labels;
  std::vector<double> trapdoor_displacement;  // m, each layer's snapshot (not less the reference)
  std::vector<std::size_t> matched_particles;  // particles in each layer's analysis
  FloatStack vertical_displacement;  // m, w (positive up: settlement is negative)
  FloatStack gamma_max;              // -, total maximum shear strain (White & Bolton 2004)
  FloatStack volumetric_strain;      // -, compression positive

  std::size_t layers() const { return labels.size(); }
};

// The default grid spacing: one mean diameter of the viewed particles, the scale below which the
// constant-strain triangles hold no information (they span about one diameter).
inline constexpr double kFieldHistorySpacingDiameters = 1.0;

// Loads snapshot k of a series (0-based, as in `displacements`).
using FrameLoader = std::function<AnalysisFrame(std::size_t)>;

// The history over a series of snapshots at `displacements` (m of trapdoor travel), loaded one at a
// time (the reference and one more in memory). settings.reference chooses the reference as for
// `trapdem analyze`; settings.at and settings.incremental are ignored. spacing (m) 0: one mean
// diameter. Throws InputError if no snapshot comes after the reference.
FieldHistory field_history(const std::vector<double>& displacements, const FrameLoader& load_frame,
                           const SpecimenGeometry& geometry, AnalysisSettings settings, double spacing = 0.0);

// The same over a run's snapshots.h5 (clumps on their grains' centres, as the analysis does).
FieldHistory field_history_of_snapshot_file(const std::filesystem::path& h5, const SpecimenGeometry& geometry,
                                            const AnalysisSettings& settings, double spacing = 0.0);

// Written atomically (format "trapdem-field-history", version 1); read back with its checks (a file
// of another format, or layers that disagree with the grid, is a FileError naming the file).
void write_field_history(const std::filesystem::path& h5, const FieldHistory& history);
FieldHistory read_field_history(const std::filesystem::path& h5);

}  // namespace trapdem
