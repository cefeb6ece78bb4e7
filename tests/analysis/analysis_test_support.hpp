#pragma once
// Shared set-up of the strain tests: a jittered packing of 2 mm particles, triangulated and
// filtered as the analysis does, and a helper to apply a displacement field to its nodes.
#include <cstdio>
#include <functional>
#include <vector>

#include "analysis/delaunay.hpp"
#include "analysis/triangle_filter.hpp"
#include "synthetic_points.hpp"

namespace trapdem::test {

struct Specimen {
  double d = 0.002;  // m, particle diameter
  std::vector<Point2> nodes;
  TriangleMesh mesh;  // filtered Delaunay mesh
};

inline Specimen make_specimen(double x_min, double x_max, double z_min, double z_max, unsigned seed,
                              double d = 0.002) {
  Specimen s;
  s.d = d;
  s.nodes = jittered_hex_lattice(x_min, x_max, z_min, z_max, d, 0.2, seed);
  TriangleFilterSettings filter;
  filter.mean_diameter = d;
  s.mesh = filter_triangles(delaunay_triangulation(s.nodes), s.nodes, filter).mesh;
  return s;
}

inline std::vector<Point2> displacements_of(const std::vector<Point2>& nodes,
                                            const std::function<Point2(Point2)>& field) {
  std::vector<Point2> u(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) u[k] = field(nodes[k]);
  return u;
}

// Prints a measured error next to its tolerance, so the test log shows the margin.
inline void report(const char* what, double measured, double tolerance) {
  std::printf("[ measured ] %s: %.3g (tolerance %.3g)\n", what, measured, tolerance);
}

}  // namespace trapdem::test
