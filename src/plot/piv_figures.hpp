#pragma once
// The figures of a PIV measurement (`trapdem piv`), each over a photograph of the sequence
// (photo_figure.hpp): the maximum shear strain of the constant-strain triangles where the soil is
// in the last image, the vertical displacement as a colour fill with labelled contours, the
// displacement vectors, and the correlation quality (ZNCC) per subset with the flagged subsets
// marked. Plain data in: src/piv converts its result (piv_output.cpp).
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"
#include "plot/contour_plot.hpp"
#include "plot/photo_figure.hpp"

namespace trapdem::plot {

// Constant-strain triangles of one strain field, in plot coordinates.
struct StrainTriangles {
  std::vector<Point2> position;      // nodes, in the image the strain is measured from
  std::vector<Point2> displacement;  // nodes, from that image to the image shown
  TriangleMesh mesh;
  std::vector<double> max_shear;     // gamma_max per triangle
};

// How a subset is drawn on the quality figure.
enum class SubsetMark {
  valid,
  poor_texture,       // too little texture in image 1: grey
  poor_texture_lost,  // the same, lost at a reference update since: grey, counted apart
  flagged             // measured but not valid (low correlation, not converged, left the image, lost): red x
};

// One subset of the grid in the image shown.
struct SubsetView {
  double x = 0.0, y = 0.0;  // px, centre in image 1
  int column = 0, row = 0;  // in the grid
  double u = std::numeric_limits<double>::quiet_NaN();  // px, displacement from image 1, x right
  double v = std::numeric_limits<double>::quiet_NaN();  // px, y down
  double zncc = std::numeric_limits<double>::quiet_NaN();
  SubsetMark mark = SubsetMark::flagged;
};

struct PivFigureData {
  std::string title;              // first part of each figure's title
  std::string unit;               // plot unit: "mm", "model units", or "px"
  Photograph first_image;         // background of the contours, vectors and quality
  Photograph last_image;          // background of the strain maps
  PixelToPlot pixel_to_plot{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::size_t image_number = 0;   // 1-based number of the image shown (the last)
  int grid_step = 0;              // px between neighbouring subset centres
  std::vector<SubsetView> subsets;       // every subset of the grid, in the image shown
  StrainTriangles total_strain;          // image 1 to the image shown
  StrainTriangles incremental_strain;    // the image before to the image shown
};

// Each writes one figure, in the format the extension names (FileError if it cannot), and returns
// where the photograph went (for marks read back by tests).
PhotoPlacement write_piv_strain_figure(const std::filesystem::path& path, const PivFigureData& data, bool incremental);
// Settlement (downward displacement, plot units) with contours at `levels` (default automatic).
PhotoPlacement write_piv_vertical_displacement_figure(const std::filesystem::path& path, const PivFigureData& data,
                                           const ContourLevels& levels = {});
PhotoPlacement write_piv_vectors_figure(const std::filesystem::path& path, const PivFigureData& data);
PhotoPlacement write_piv_quality_figure(const std::filesystem::path& path, const PivFigureData& data);

}  // namespace trapdem::plot
