#pragma once
// PIV over a photograph sequence into a folder: what `trapdem piv` does, as a library call for any
// front end (the command line, Python). Writes displacements.csv, piv.h5 (docs/piv.md) and, unless
// asked not to, the figures; returns the result, the control-point fit and what was written.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "piv/piv_output.hpp"
#include "piv/piv_result.hpp"
#include "piv/piv_settings.hpp"
#include "piv/pixel_to_model.hpp"
#include "piv/run_piv.hpp"

namespace trapdem {

struct PivFolderOptions {
  std::vector<std::filesystem::path> images;  // in order, at least two
  std::filesystem::path out;                  // the folder written (created)
  PivSettings settings;                       // subset, step, region of interest, threads
  // Model coordinates: a scale (mm per px) with the model position (mm, x right, z up) of pixel
  // (0, 0), or control points (CSV x_px,y_px,x_model,z_model) fitted affinely or projectively;
  // neither: pixels.
  std::optional<double> scale_mm_per_px;
  std::array<double, 2> origin_mm{0.0, 0.0};
  std::filesystem::path control_points;
  ControlPointFitKind fit = ControlPointFitKind::projective;
  bool figures = true;
  plot::FigureFormat format = plot::FigureFormat::png;
  plot::ContourLevels settlement_levels;  // of the vertical displacement figure, plot units
};

struct PivFolderResult {
  PivResult result;
  std::optional<ControlPointFit> fit;      // with control points
  std::vector<ControlPoint> control_points;
  std::string unit;                        // "mm", "model units" or "px"
  std::size_t subsets = 0;                 // on image 1
  double seconds = 0.0;                    // wall clock of the correlation
  PivStrainSeries strain;                  // per image: total and incremental strain (piv.h5's), in `unit`
  std::vector<std::filesystem::path> written;
};

// Throws InputError for options that do not fit together or an image that cannot be read, FileError
// when the folder cannot be written. `progress` is called after each image (image 0: the subsets
// laid out).
PivFolderResult run_piv_into_folder(const PivFolderOptions& options, const PivProgress& progress = {});

}  // namespace trapdem
