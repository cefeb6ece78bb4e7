#pragma once
// Contour lines of a grid field by marching squares: in each grid cell whose four corners are
// defined (no NaN), the level crossings on the cell edges, interpolated linearly, joined into
// segments; saddle cells are resolved by the mean of the four corners. Segments sharing a cell
// edge are chained into polylines (closed ones end where they start).
#include <vector>

#include "analysis/grid_field.hpp"
#include "analysis/point_set.hpp"

namespace trapdem::plot {

struct ContourLine {
  std::vector<Point2> points;  // in the grid's coordinates
  bool closed = false;
  double length() const;
};

// The polylines where `field` crosses `level` (a corner exactly at the level counts as above).
std::vector<ContourLine> contour_lines(const GridField& field, double level);

}  // namespace trapdem::plot
