#include "analysis/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace trapdem {

namespace {
double distance(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.z - a.z); }
}  // namespace

std::array<Point2, 3> triangle_corners(const TriangleNodes& t, const std::vector<Point2>& nodes) {
  return {nodes[t[0]], nodes[t[1]], nodes[t[2]]};
}

Point2 triangle_centroid(const std::array<Point2, 3>& c) {
  return {(c[0].x + c[1].x + c[2].x) / 3.0, (c[0].z + c[1].z + c[2].z) / 3.0};
}

double triangle_area(const std::array<Point2, 3>& c) { return 0.5 * std::abs(twice_signed_area(c[0], c[1], c[2])); }

double longest_edge(const std::array<Point2, 3>& c) {
  return std::max({distance(c[0], c[1]), distance(c[1], c[2]), distance(c[2], c[0])});
}

double smallest_angle_deg(const std::array<Point2, 3>& c) {
  // Law of cosines at each corner; the smallest angle faces the shortest edge.
  const double a = distance(c[1], c[2]), b = distance(c[2], c[0]), e = distance(c[0], c[1]);
  const double shortest = std::min({a, b, e});
  if (shortest == 0.0) return 0.0;
  double p, q;  // the two edges enclosing the smallest angle
  if (shortest == a) {
    p = b; q = e;
  } else if (shortest == b) {
    p = a; q = e;
  } else {
    p = a; q = b;
  }
  const double cosine = std::clamp((p * p + q * q - shortest * shortest) / (2.0 * p * q), -1.0, 1.0);
  return std::acos(cosine) * 180.0 / std::numbers::pi;
}

double radius_ratio(const std::array<Point2, 3>& c) {
  // R = abc / (4A), r = A / s with s the semi-perimeter, so R / (2r) = abc s / (8 A^2).
  const double a = distance(c[1], c[2]), b = distance(c[2], c[0]), e = distance(c[0], c[1]);
  const double area = triangle_area(c);
  if (area == 0.0) return std::numeric_limits<double>::infinity();
  const double s = 0.5 * (a + b + e);
  return a * b * e * s / (8.0 * area * area);
}

std::vector<Point2> triangle_centroids(const TriangleMesh& mesh, const std::vector<Point2>& nodes) {
  std::vector<Point2> centroids(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) centroids[t] = triangle_centroid(triangle_corners(mesh.triangles[t], nodes));
  return centroids;
}

std::vector<double> triangle_areas(const TriangleMesh& mesh, const std::vector<Point2>& nodes) {
  std::vector<double> areas(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) areas[t] = triangle_area(triangle_corners(mesh.triangles[t], nodes));
  return areas;
}

}  // namespace trapdem
