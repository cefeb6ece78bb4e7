// Regular-grid resampling: linear fields reproduced exactly inside the mesh, NaN outside it.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/grid_interpolation.hpp"
#include "analysis_test_support.hpp"

using namespace trapdem;
using test::report;

// Linear interpolation inside a triangle reproduces any linear field; the round-off is that of
// a barycentric combination of O(1) values: 1e-12 is a thousand times above it.
TEST(GridInterpolation, LinearFieldExactInsideAndNaNOutside) {
  const auto s = test::make_specimen(0.0, 0.06, 0.0, 0.04, 21);
  std::vector<double> value(s.nodes.size());
  for (std::size_t k = 0; k < s.nodes.size(); ++k) value[k] = 3.0 + 20.0 * s.nodes[k].x - 7.0 * s.nodes[k].z;

  GridSpec grid{-0.01, -0.01, 0.001, 81, 61};  // 10 mm beyond the specimen on every side
  const GridField field = interpolate_nodal_field(s.mesh, s.nodes, value, grid);
  double error = 0.0;
  std::size_t inside = 0;
  for (std::size_t j = 0; j < grid.nz; ++j) {
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double x = grid.x(i), z = grid.z(j);
      const double v = field.at(i, j);
      const bool outside_box = x < -0.001 || x > 0.061 || z < -0.001 || z > 0.041;  // beyond nodes + jitter
      if (outside_box) {
        EXPECT_TRUE(std::isnan(v)) << "x " << x << " z " << z;
      }
      if (std::isfinite(v)) {
        ++inside;
        error = std::max(error, std::abs(v - (3.0 + 20.0 * x - 7.0 * z)));
      }
    }
  }
  report("linear field on grid, max error", error, 1e-12);
  EXPECT_LE(error, 1e-12);
  // The interior (2 mm in from the edges, 56 x 36 mm at 1 mm) is covered.
  EXPECT_GE(inside, 57u * 37u);
}

TEST(GridInterpolation, GridCoveringSpansTheNodes) {
  const GridSpec g = grid_covering({{0.0013, 0.0021}, {0.0507, 0.0305}}, 0.001);
  EXPECT_NEAR(g.x0, 0.001, 1e-15);
  EXPECT_NEAR(g.z0, 0.002, 1e-15);
  EXPECT_GE(g.x(g.nx - 1), 0.0507);
  EXPECT_GE(g.z(g.nz - 1), 0.0305);
  EXPECT_LT(g.x(g.nx - 2), 0.0507);
  EXPECT_THROW(grid_covering({{0, 0}}, 0.0), std::runtime_error);
}

// Piecewise-constant sampling of a per-triangle field: each grid node gets the value of a
// triangle containing it. With value = centroid x, the sample differs from the node's own x by
// less than a triangle's size (the filter keeps edges within 2 d).
TEST(GridInterpolation, TriangleFieldSampledFromTheContainingTriangle) {
  const auto s = test::make_specimen(0.0, 0.04, 0.0, 0.04, 22);
  const auto centroids = triangle_centroids(s.mesh, s.nodes);
  std::vector<double> value(s.mesh.size());
  for (std::size_t t = 0; t < s.mesh.size(); ++t) value[t] = centroids[t].x;
  const GridSpec grid = grid_covering(s.nodes, 0.0005);
  const GridField field = sample_triangle_field(s.mesh, s.nodes, value, grid);
  std::size_t finite = 0;
  for (std::size_t j = 0; j < grid.nz; ++j) {
    for (std::size_t i = 0; i < grid.nx; ++i) {
      if (!std::isfinite(field.at(i, j))) continue;
      ++finite;
      EXPECT_LT(std::abs(field.at(i, j) - grid.x(i)), 2.0 * s.d);
    }
  }
  EXPECT_GT(finite, grid.nx * grid.nz / 2);
}
