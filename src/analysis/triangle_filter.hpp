#pragma once
// Leaves out triangles that are not soil elements: those spanning voids, the free surface or the
// convex hull (an edge much longer than a particle diameter) and slivers (a tiny angle or a large
// aspect ratio, whose strain is dominated by the position noise of one node).
#include <cstddef>
#include <limits>
#include <vector>

#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

struct TriangleFilterSettings {
  double mean_diameter = 0.0;         // m, mean particle diameter; must be positive
  double max_edge_in_diameters = 2.0;  // drop if the longest edge exceeds this multiple of mean_diameter
  double min_angle_deg = 10.0;         // drop if the smallest interior angle is below (0 disables)
  double max_radius_ratio = std::numeric_limits<double>::infinity();  // drop if R/(2r) exceeds (inf disables)
};

struct FilteredMesh {
  TriangleMesh mesh;                       // the triangles kept, in input order
  std::vector<std::size_t> source_index;   // for each kept triangle, its index in the input mesh
  std::size_t dropped_long_edge = 0;       // longest edge above the limit (checked first)
  std::size_t dropped_sliver = 0;          // small angle or large radius ratio (edge test passed)
  TriangleMesh dropped;                    // the triangles left out, in input order (hole_fill.hpp)
};

// Applies the tests in the reference configuration `nodes`. Throws InputError if
// mean_diameter is not positive.
FilteredMesh filter_triangles(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                              const TriangleFilterSettings& settings);

}  // namespace trapdem
