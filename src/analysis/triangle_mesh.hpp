#pragma once
// A triangle mesh over a node set: three node indices per triangle, counter-clockwise in the
// reference configuration (positive signed area with x to the right and z up). Each triangle is a
// soil element: the same node triple is followed through every configuration (Lagrangian).
#include <array>
#include <cstddef>
#include <vector>

#include "analysis/point_set.hpp"

namespace trapdem {

using TriangleNodes = std::array<std::size_t, 3>;

struct TriangleMesh {
  std::vector<TriangleNodes> triangles;

  std::size_t size() const { return triangles.size(); }
};

// Twice the signed area of (a, b, c): positive when counter-clockwise (x right, z up).
constexpr double twice_signed_area(Point2 a, Point2 b, Point2 c) {
  return (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
}

// The three corner positions of triangle t.
std::array<Point2, 3> triangle_corners(const TriangleNodes& t, const std::vector<Point2>& nodes);

Point2 triangle_centroid(const std::array<Point2, 3>& corners);
double triangle_area(const std::array<Point2, 3>& corners);  // m^2, unsigned
double longest_edge(const std::array<Point2, 3>& corners);   // m
double smallest_angle_deg(const std::array<Point2, 3>& corners);
// Radius ratio R / (2 r) (circumradius over twice the inradius): 1 for an equilateral
// triangle, growing without bound as the triangle flattens; infinite when degenerate.
double radius_ratio(const std::array<Point2, 3>& corners);

// Per-triangle centroids and areas, in mesh order.
std::vector<Point2> triangle_centroids(const TriangleMesh& mesh, const std::vector<Point2>& nodes);
std::vector<double> triangle_areas(const TriangleMesh& mesh, const std::vector<Point2>& nodes);

}  // namespace trapdem
