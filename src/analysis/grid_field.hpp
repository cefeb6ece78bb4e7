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

// The most memory one grid field may take: 1 GiB of doubles (134 M nodes; a 0.3 m box at 30 um).
// A spacing given by a user (analyze --grid, compare --grid) is checked against it before anything
// is allocated, instead of ending in std::bad_alloc.
inline constexpr double kMaxGridFieldBytes = 1024.0 * 1024.0 * 1024.0;

// Throws InputError if a grid of `spacing` (m) over `width` x `height` (m) would hold more than
// kMaxGridFieldBytes per field, or the spacing is not a positive finite number: "<what> <spacing>
// m over 80 x 40 mm: 3.2e+15 nodes, 2.6e+16 bytes per field; expected at most 1 GiB per field, a
// spacing of at least 3.1e-06 m".
void check_grid_memory(double width, double height, double spacing, const char* what);

// The smallest grid of the given spacing whose nodes are multiples of the spacing and which
// covers the bounding box of `nodes`. Throws InputError if spacing is not positive or nodes empty,
// or the grid is too large (check_grid_memory).
GridSpec grid_covering(const std::vector<Point2>& nodes, double spacing);

}  // namespace trapdem
