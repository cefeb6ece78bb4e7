#pragma once
// The overlay figure of `trapdem compare`: DEM settlement contours (solid) and PIV settlement
// contours (dashed) at the same levels, over the compared area (shaded), the box outline and the
// lowered trapdoor, with a legend and the error in the title. Coordinates: trapdoor centre at
// the origin, axes in mm.
#include <filesystem>
#include <string>

#include "analysis/grid_field.hpp"

namespace trapdem::plot {

struct ComparisonFigure {
  std::string title;     // first line, bold
  std::string subtitle;  // further lines separated by '\n'
  GridField dem, piv;    // m, vertical displacement (up positive) on one grid, NaN outside the compared area
  double box_left = 0.0, box_right = 0.0;  // m, box walls relative to the trapdoor centre
  double box_height = 0.0;                 // m, above the trapdoor's initial level
  double trapdoor_width = 0.0;             // m
  double trapdoor_travel = 0.0;            // m, drawn at z = -travel
  std::string dem_label = "DEM", piv_label = "PIV";
};

// Writes the figure (width layout units, the height following the box's aspect; the extension picks the
// format). Throws FileError on failure.
void write_comparison_figure(const std::filesystem::path& path, const ComparisonFigure& figure, int width = 640);

}  // namespace trapdem::plot
