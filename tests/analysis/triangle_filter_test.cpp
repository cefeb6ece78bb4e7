// The triangle filter: long edges (voids, hull) and slivers are dropped and counted.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/delaunay.hpp"
#include "analysis/triangle_filter.hpp"
#include "synthetic_points.hpp"

using namespace trapdem;

TEST(TriangleFilter, EquilateralKeptFlatTriangleDroppedAsSliver) {
  // Triangle 0: equilateral of side 1 mm. Triangle 1: isosceles with a 5 degree apex (sliver).
  const double s = 0.001;
  const double apex = 5.0 * std::numbers::pi / 180.0;
  const std::vector<Point2> nodes{{0, 0},
                                  {s, 0},
                                  {0.5 * s, s * std::sqrt(3.0) / 2},
                                  {0.01, 0},
                                  {0.01 + s, 0},
                                  {0.01 + 0.5 * s, 0.5 * s / std::tan(0.5 * apex)}};
  TriangleMesh mesh;
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  TriangleFilterSettings settings;
  settings.mean_diameter = 0.002;
  settings.max_edge_in_diameters = 10.0;  // 20 mm: the edge test passes for both
  const FilteredMesh kept = filter_triangles(mesh, nodes, settings);
  ASSERT_EQ(kept.mesh.size(), 1u);
  EXPECT_EQ(kept.source_index[0], 0u);
  EXPECT_EQ(kept.dropped_sliver, 1u);
  EXPECT_EQ(kept.dropped_long_edge, 0u);

  EXPECT_NEAR(smallest_angle_deg(triangle_corners(mesh.triangles[0], nodes)), 60.0, 1e-9);
  EXPECT_NEAR(smallest_angle_deg(triangle_corners(mesh.triangles[1], nodes)), 5.0, 1e-9);
  EXPECT_NEAR(radius_ratio(triangle_corners(mesh.triangles[0], nodes)), 1.0, 1e-12);

  // The same sliver caught by the radius ratio alone.
  settings.min_angle_deg = 0.0;
  settings.max_radius_ratio = 3.0;
  EXPECT_EQ(filter_triangles(mesh, nodes, settings).dropped_sliver, 1u);
  settings.max_radius_ratio = std::numeric_limits<double>::infinity();
  EXPECT_EQ(filter_triangles(mesh, nodes, settings).dropped_sliver, 0u);
}

// A void of radius 5 d in a jittered packing: the Delaunay triangles across it have edges of
// ~10 d and must all go; every kept triangle has its longest edge within the limit.
TEST(TriangleFilter, TrianglesAcrossAVoidAreDroppedAndCounted) {
  const double d = 0.002;
  auto lattice = test::jittered_hex_lattice(0.0, 0.06, 0.0, 0.06, d, 0.2, 11);
  std::vector<Point2> nodes;
  for (const auto& p : lattice) {
    if (std::hypot(p.x - 0.03, p.z - 0.03) > 5 * d) nodes.push_back(p);
  }
  const TriangleMesh mesh = delaunay_triangulation(nodes);
  TriangleFilterSettings settings;
  settings.mean_diameter = d;
  const FilteredMesh kept = filter_triangles(mesh, nodes, settings);

  EXPECT_EQ(kept.mesh.size() + kept.dropped_long_edge + kept.dropped_sliver, mesh.size());
  EXPECT_GT(kept.dropped_long_edge, 10u) << "the void is spanned by many long triangles";
  for (const auto& t : kept.mesh.triangles) {
    const auto c = triangle_corners(t, nodes);
    EXPECT_LE(longest_edge(c), 2.0 * d);
    EXPECT_GE(smallest_angle_deg(c), 10.0);
    EXPECT_GT(std::hypot(triangle_centroid(c).x - 0.03, triangle_centroid(c).z - 0.03), 4 * d)
        << "no kept triangle inside the void";
  }
}

TEST(TriangleFilter, RejectsNonPositiveDiameter) {
  EXPECT_THROW(filter_triangles({}, {}, TriangleFilterSettings{}), std::runtime_error);
}
