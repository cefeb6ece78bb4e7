#pragma once
// A uniform grid of cells no smaller than the interaction range, for the neighbour search and
// for ordering particles in space.
#include <array>
#include <cstdint>
#include <vector>

#include "dem/domain.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct CellGrid {
  Vec3 origin;                    // m, corner of cell (0,0,0)
  Vec3 cell_size;                 // m, >= the requested minimum on every axis
  std::array<int, 3> count{1, 1, 1};
  bool periodic[3] = {false, false, false};
  // Linear cell index = sum of coordinate x stride. The axis with the most cells varies slowest,
  // so that the cells next to a cell in index order span the two shorter axes only: the particles
  // a sweep in index order keeps touching then stay few (in cache) even in a long, wide box.
  std::array<std::size_t, 3> stride{1, 1, 1};

  // Covers the particles' bounding box on bounded axes and the domain on periodic ones. The
  // number of cells is capped near `max_cells` by enlarging cells (a stray particle far away must
  // not make the grid huge).
  static CellGrid covering(const std::vector<Vec3>& positions, const Domain& domain, double min_cell_size,
                           std::size_t max_cells);

  std::size_t total() const { return std::size_t(count[0]) * count[1] * count[2]; }
  int coordinate(const Vec3& x, int axis) const {
    int c = static_cast<int>((x[axis] - origin[axis]) / cell_size[axis]);
    return c < 0 ? 0 : (c >= count[axis] ? count[axis] - 1 : c);
  }
  std::uint32_t index(const Vec3& x) const {
    return static_cast<std::uint32_t>(coordinate(x, 0) * stride[0] + coordinate(x, 1) * stride[1] +
                                      coordinate(x, 2) * stride[2]);
  }
  // The distinct cells within one cell of `cell` (itself included), wrapping on periodic axes.
  int neighbours(std::uint32_t cell, std::array<std::uint32_t, 27>& out) const;
};

}  // namespace trapdem
