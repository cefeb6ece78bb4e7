#pragma once
// What `trapdem piv` writes besides displacements.csv: piv.h5 (subset grid, per image u, v, ZNCC,
// status, model coordinates, strain fields) and the figures (shear strain over the photograph,
// vertical displacement contours, vectors, correlation quality). Layout: docs/piv.md.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "piv/piv_result.hpp"
#include "piv/piv_strain.hpp"
#include "piv/pixel_to_model.hpp"
#include "plot/contour_plot.hpp"
#include "plot/figure_format.hpp"

namespace trapdem {

// Strain of every image k >= 1: total (image 1 -> k) and incremental (k-1 -> k).
struct PivStrainSeries {
  std::vector<PivStrainField> total;        // index k (entry 0 empty)
  std::vector<PivStrainField> incremental;  // index k (entry 0 empty)
};

// Strain through the analysis module for every image; images with too few valid subsets for a
// triangle get an empty field (no throw).
PivStrainSeries compute_piv_strain(const PivResult& result, const PixelToModel& to_model_units);

// piv.h5, written atomically. `model`: the pixel-to-model transform if the user gave a scale or
// control points (model coordinates are then written too); `unit` names the model unit ("mm").
void write_piv_h5(const std::filesystem::path& path, const PivResult& result, const std::vector<std::string>& names,
                  const std::optional<PixelToModel>& model, const std::string& unit, const PivStrainSeries& strain);

struct PivFigureInput {
  const PivResult* result = nullptr;
  const PivStrainSeries* strain = nullptr;
  cv::Mat first_image;   // CV_8U grey, image 1 (background of vectors, contours, quality)
  cv::Mat last_image;    // CV_8U grey, the last image (background of the strain map)
  PixelToModel to_plot;  // pixels -> figure coordinates (model units z up; or px with y flipped)
  std::string unit;      // "mm", or "px"
  std::string title;     // first line of each figure's title
  plot::FigureFormat format = plot::FigureFormat::png;
  plot::ContourLevels settlement_levels;  // of the vertical displacement figure, plot units
};

// Writes shear_strain, shear_strain_incremental, vertical_displacement, vectors and
// correlation_quality (.png, .svg or .pdf: input.format) to `dir`, drawn by src/plot/piv_figures.hpp from the result converted to
// plain data; returns the files written.
std::vector<std::filesystem::path> write_piv_figures(const std::filesystem::path& dir, const PivFigureInput& input);

// An image as 8-bit grey for figure backgrounds (any depth or channel count).
cv::Mat to_grey8(const cv::Mat& image);

}  // namespace trapdem
