// Dropped triangles inside a mesh drawn with their neighbours' values (src/analysis/hole_fill.hpp,
// issue 41): holes inside are filled layer by layer from the kept triangles, dropped triangles that
// reach the outer boundary through dropped ones stay empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/hole_fill.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

// A square grid of n x n cells, each split into two triangles (2 n^2 triangles; triangle 2 (i + n j)
// and 2 (i + n j) + 1 in cell (i, j)), all kept.
TriangleMesh grid_mesh(std::size_t n) {
  TriangleMesh mesh;
  const auto node = [n](std::size_t i, std::size_t j) { return i + (n + 1) * j; };
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      mesh.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  return mesh;
}

// The grid with the triangles in `drop` moved to the dropped list; kept values: the triangle's
// index in the full grid (so a neighbour's value names it).
FilteredMesh with_dropped(const TriangleMesh& full, const std::vector<std::size_t>& drop, std::vector<double>& values) {
  FilteredMesh m;
  values.clear();
  for (std::size_t t = 0; t < full.size(); ++t) {
    if (std::find(drop.begin(), drop.end(), t) != drop.end()) {
      m.dropped.triangles.push_back(full.triangles[t]);
      ++m.dropped_long_edge;
    } else {
      m.mesh.triangles.push_back(full.triangles[t]);
      m.source_index.push_back(t);
      values.push_back(double(t));
    }
  }
  return m;
}

}  // namespace

// One triangle dropped in the middle of a 4 x 4 grid: filled with the mean of its three
// neighbours. Triangle 2 (1 + 4) + 1 = 11 (the upper one of cell (1, 1), corners (1,1) (2,2)
// (1,2)) borders 10 (its cell's lower triangle, across the diagonal), 18 (the lower one of cell
// (1, 2), across the top edge) and 8 (the lower one of cell (0, 1), across the left edge).
TEST(HoleFill, OneTriangleInsideTakesItsNeighboursMean) {
  std::vector<double> values;
  const FilteredMesh m = with_dropped(grid_mesh(4), {11}, values);
  const FilledHoles f = fill_interior_holes(m, values);
  ASSERT_EQ(f.triangles.size(), 1u);
  EXPECT_EQ(f.left_empty, 0u);
  EXPECT_NEAR(f.values[0], (8.0 + 10.0 + 18.0) / 3.0, 1e-12);
}

// A hole of 2 x 2 cells (8 triangles): six fill from their kept neighbours; two have none (the
// lower triangle of cell (2, 3) and the upper one of cell (3, 2): all three of their edges face
// dropped triangles) and fill from the first layer in a second one, so all 8 are filled. Every
// value lies within the kept values' range (a mean of means).
TEST(HoleFill, DeeperHolesFillLayerByLayer) {
  std::vector<double> values;
  // A 6 x 6 grid with the 2 x 2 block of cells (2..3, 2..3) dropped (8 triangles).
  std::vector<std::size_t> drop;
  for (std::size_t j = 2; j <= 3; ++j)
    for (std::size_t i = 2; i <= 3; ++i) {
      drop.push_back(2 * (i + 6 * j));
      drop.push_back(2 * (i + 6 * j) + 1);
    }
  const FilteredMesh m = with_dropped(grid_mesh(6), drop, values);
  const FilledHoles f = fill_interior_holes(m, values);
  EXPECT_EQ(f.triangles.size(), 8u);
  EXPECT_EQ(f.left_empty, 0u);
  const double lo = *std::min_element(values.begin(), values.end());
  const double hi = *std::max_element(values.begin(), values.end());
  for (const double v : f.values) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GT(v, lo);
    EXPECT_LT(v, hi);
  }
}

// Dropped triangles along the boundary, and a dropped strip reaching in from it, are empty space
// (the free surface): left blank, while a separate hole inside is filled.
TEST(HoleFill, DroppedTrianglesReachingTheBoundaryStayEmpty) {
  std::vector<double> values;
  // 6 x 6 grid: the top row's cells (j = 5) dropped, and below it cell (2, 4) too (connected to
  // the top row through its upper triangle); cell (4, 1)'s upper triangle is a hole inside.
  std::vector<std::size_t> drop;
  for (std::size_t i = 0; i < 6; ++i) {
    drop.push_back(2 * (i + 6 * 5));
    drop.push_back(2 * (i + 6 * 5) + 1);
  }
  drop.push_back(2 * (2 + 6 * 4));
  drop.push_back(2 * (2 + 6 * 4) + 1);
  const std::size_t inside = 2 * (4 + 6 * 1) + 1;
  drop.push_back(inside);
  const FilteredMesh m = with_dropped(grid_mesh(6), drop, values);
  const FilledHoles f = fill_interior_holes(m, values);
  ASSERT_EQ(f.triangles.size(), 1u);
  EXPECT_EQ(f.left_empty, drop.size() - 1);
  EXPECT_EQ(f.triangles.triangles[0], grid_mesh(6).triangles[inside]);
}

TEST(HoleFill, NothingDroppedNothingFilled) {
  std::vector<double> values;
  const FilteredMesh m = with_dropped(grid_mesh(3), {}, values);
  const FilledHoles f = fill_interior_holes(m, values);
  EXPECT_EQ(f.triangles.size(), 0u);
  EXPECT_EQ(f.left_empty, 0u);
}

TEST(HoleFill, ValuesMustMatchTheKeptTriangles) {
  std::vector<double> values;
  const FilteredMesh m = with_dropped(grid_mesh(3), {4}, values);
  values.pop_back();
  EXPECT_THROW(fill_interior_holes(m, values), InputError);
}

namespace {

// A grid field from rows written top row first, as it would be drawn ('.' a NaN node, a digit its
// value), node (i, j) at x = i, z = j.
GridField grid_from_rows(const std::vector<std::string>& rows_top_first) {
  GridField f;
  f.grid.spacing = 1.0;
  f.grid.nz = rows_top_first.size();
  f.grid.nx = rows_top_first.front().size();
  f.value.assign(f.grid.nx * f.grid.nz, std::nan(""));
  for (std::size_t r = 0; r < rows_top_first.size(); ++r)
    for (std::size_t i = 0; i < f.grid.nx; ++i) {
      const char c = rows_top_first[r][i];
      if (c != '.') f.value[(f.grid.nz - 1 - r) * f.grid.nx + i] = double(c - '0');
    }
  return f;
}

double at_row(const GridField& f, std::size_t i, std::size_t row_from_top) { return f.at(i, f.grid.nz - 1 - row_from_top); }

}  // namespace

// A specimen under empty space: its one uncovered node takes the mean of its four neighbours; a
// pair of uncovered nodes fills from the values around it (each node the mean of its finite
// neighbours), as does a node beside a side wall; the empty space above, the crater open to it and
// the space below the base (open to the bottom row) stay empty.
TEST(GridHoleFill, InteriorNodesFillAndEmptySpaceStaysEmpty) {
  const GridField f = grid_from_rows({".........",   //
                                      "22.222222",   // a crater, open to the space above
                                      "22.212222",   //
                                      "2224.4222",   // one node inside: (4 + 4 + 2 + 1) / 4
                                      "22222222.",   // beside the right wall
                                      "2..222222",   // two nodes side by side
                                      "2222222.."});  // below the base
  std::size_t filled = 0;
  const GridField g = fill_interior_grid_holes(f, -0.5, 8.5, &filled);
  EXPECT_EQ(filled, 4u);
  EXPECT_DOUBLE_EQ(at_row(g, 4, 3), (4.0 + 4.0 + 1.0 + 2.0) / 4.0);
  EXPECT_DOUBLE_EQ(at_row(g, 8, 4), 2.0);
  EXPECT_TRUE(std::isnan(at_row(g, 7, 6)));
  EXPECT_TRUE(std::isnan(at_row(g, 8, 6)));
  EXPECT_DOUBLE_EQ(at_row(g, 1, 5), 2.0);  // its neighbours are all 2 (the other hole node not yet filled)
  EXPECT_DOUBLE_EQ(at_row(g, 2, 5), 2.0);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_TRUE(std::isnan(at_row(g, i, 0))) << "empty space above, column " << i;
  EXPECT_TRUE(std::isnan(at_row(g, 2, 1)));  // the crater
  EXPECT_TRUE(std::isnan(at_row(g, 2, 2)));
  // Every node with a value keeps it.
  for (std::size_t k = 0; k < f.value.size(); ++k)
    if (std::isfinite(f.value[k])) EXPECT_EQ(g.value[k], f.value[k]) << "node " << k;
}

// A deeper hole fills inward, layer by layer: the ring first, then the centre from the ring.
TEST(GridHoleFill, ADeeperHoleFillsLayerByLayer) {
  const GridField f = grid_from_rows({"44444",  //
                                      "4...4",  //
                                      "4...4",  //
                                      "4...4",  //
                                      "44444"});
  std::size_t filled = 0;
  const GridField g = fill_interior_grid_holes(f, -0.5, 8.5, &filled);
  EXPECT_EQ(filled, 9u);
  for (double v : g.value) EXPECT_DOUBLE_EQ(v, 4.0);  // a constant field stays constant
  // Without an interior hole nothing changes.
  std::size_t none = 1;
  const GridField h = fill_interior_grid_holes(grid_from_rows({"...", "123", "456", "7.."}), -0.5, 2.5, &none);
  EXPECT_EQ(none, 0u);
  EXPECT_TRUE(std::isnan(at_row(h, 1, 0)));
  EXPECT_TRUE(std::isnan(at_row(h, 1, 3)));
  GridField bad = f;
  bad.value.pop_back();
  EXPECT_THROW(fill_interior_grid_holes(bad, -0.5, 4.5), InputError);
}

// A grid wider than the box (its columns cover the triangles' nodes, in steps of the spacing): a
// column beyond the right wall holds no value at all, and is no way out for a node beside the wall.
TEST(GridHoleFill, BeyondTheWallsIsNoWayOut) {
  const GridField f = grid_from_rows({"......",  //
                                      "22222.",  //
                                      "2222..",  // beside the wall at x = 4.5
                                      "22222.",  //
                                      "22222."});
  std::size_t filled = 0;
  const GridField g = fill_interior_grid_holes(f, -0.5, 4.5, &filled);
  EXPECT_EQ(filled, 1u);
  EXPECT_DOUBLE_EQ(at_row(g, 4, 2), 2.0);
  for (std::size_t row = 0; row < 5; ++row) EXPECT_TRUE(std::isnan(at_row(g, 5, row))) << "beyond the wall, row " << row;
  // With the wall past the last column, that column is open space, and the node beside it with it.
  const GridField open = fill_interior_grid_holes(f, -0.5, 5.5, &filled);
  EXPECT_EQ(filled, 0u);
  EXPECT_TRUE(std::isnan(at_row(open, 4, 2)));
  // With the wall on the last column, the column is the wall's (no particle centre reaches it):
  // no way out either, and it stays empty.
  const GridField on_wall = fill_interior_grid_holes(f, 0.0, 5.0, &filled);
  EXPECT_EQ(filled, 1u);
  EXPECT_DOUBLE_EQ(at_row(on_wall, 4, 2), 2.0);
  EXPECT_TRUE(std::isnan(at_row(on_wall, 5, 2)));
}
