#pragma once
// A scalar field sampled on a regular grid (for contour plots): node (i, j) sits at
// x = x0 + i * spacing, z = z0 + j * spacing; values are stored row by row (j outer), NaN where the
// field is not defined (outside the kept triangles).
#include <cstddef>
#include <vector>

#include "analysis/point_set.hpp"

namespace trapdem {

struct GridSpec {
  double x0 = 0.0;       // m, first column
  double z0 = 0.0;       // m, first row
  double spacing = 0.0;  // m, same along x and z
  std::size_t nx = 0;
  std::size_t nz = 0;

  double x(std::size_t i) const { return x0 + static_cast<double>(i) * spacing; }
  double z(std::size_t j) const { return z0 + static_cast<double>(j) * spacing; }
};

struct GridField {
  GridSpec grid;
  std::vector<double> value;  // nx * nz, index j * nx + i

  double at(std::size_t i, std::size_t j) const { return value[j * grid.nx + i]; }
};

// The smallest grid of the given spacing whose nodes are multiples of the spacing and which
// covers the bounding box of `nodes`. Throws InputError if spacing is not positive or nodes empty.
GridSpec grid_covering(const std::vector<Point2>& nodes, double spacing);

}  // namespace trapdem
