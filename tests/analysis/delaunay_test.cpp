// Delaunay triangulation (CGAL): counter-clockwise triangles, Euler's count, empty circumcircles.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "analysis/delaunay.hpp"
#include "synthetic_points.hpp"

using namespace trapdem;

TEST(Delaunay, SquareWithCentreGivesFourCounterClockwiseTriangles) {
  const std::vector<Point2> nodes{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const TriangleMesh mesh = delaunay_triangulation(nodes);
  ASSERT_EQ(mesh.size(), 4u);
  for (const auto& t : mesh.triangles) {
    EXPECT_GT(twice_signed_area(nodes[t[0]], nodes[t[1]], nodes[t[2]]), 0.0);
    EXPECT_TRUE(t[0] == 4 || t[1] == 4 || t[2] == 4) << "every triangle has the centre node";
  }
}

TEST(Delaunay, CollinearOrTooFewNodesGiveNoTriangles) {
  EXPECT_EQ(delaunay_triangulation({{0, 0}, {1, 0}}).size(), 0u);
  EXPECT_EQ(delaunay_triangulation({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).size(), 0u);
}

// Euler: a triangulation of n points with h on the convex hull has 2n - 2 - h triangles; the
// hull edges are the edges that belong to one triangle only. And no node lies strictly inside any
// triangle's circumcircle (the Delaunay property), checked by brute force.
TEST(Delaunay, JitteredPointsSatisfyEulerAndEmptyCircumcircles) {
  const double d = 0.002;
  const auto nodes = test::jittered_hex_lattice(0.0, 0.04, 0.0, 0.03, d, 0.2, 7);
  const TriangleMesh mesh = delaunay_triangulation(nodes);

  std::map<std::pair<std::size_t, std::size_t>, int> edge_use;
  for (const auto& t : mesh.triangles) {
    ASSERT_GT(twice_signed_area(nodes[t[0]], nodes[t[1]], nodes[t[2]]), 0.0);
    for (int e = 0; e < 3; ++e) {
      auto a = t[e], b = t[(e + 1) % 3];
      ++edge_use[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::size_t hull_edges = 0;
  for (const auto& [edge, uses] : edge_use) hull_edges += (uses == 1);
  EXPECT_EQ(mesh.size(), 2 * nodes.size() - 2 - hull_edges);

  for (const auto& t : mesh.triangles) {
    const Point2 a = nodes[t[0]], b = nodes[t[1]], c = nodes[t[2]];
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (k == t[0] || k == t[1] || k == t[2]) continue;
      const Point2 p = nodes[k];
      // In-circle determinant, positive when p is inside the circumcircle of CCW (a, b, c).
      const double ax = a.x - p.x, az = a.z - p.z, bx = b.x - p.x, bz = b.z - p.z, cx = c.x - p.x, cz = c.z - p.z;
      const double det = (ax * ax + az * az) * (bx * cz - cx * bz) - (bx * bx + bz * bz) * (ax * cz - cx * az) +
                         (cx * cx + cz * cz) * (ax * bz - bx * az);
      // Scale: d^4 = 1.6e-11; round-off far below 1e-6 of it.
      ASSERT_LE(det, 1e-6 * d * d * d * d) << "node " << k << " inside a circumcircle";
    }
  }
}
