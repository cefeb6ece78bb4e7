#pragma once
// Delaunay triangulation of the reference particle centres (CGAL), as the paper does to build
// its constant strain triangles (seed paper, section 4.3).
#include <vector>

#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

// Triangles of the Delaunay triangulation of `nodes`, each counter-clockwise, node indices into
// `nodes`. The convex hull is covered; long hull triangles are removed by filter_triangles.
// Coincident nodes: only the first is triangulated, the others belong to no triangle.
// The output order is canonical (sorted), so the same input always gives the same mesh.
// Fewer than three distinct nodes, or all on a line, give an empty mesh.
TriangleMesh delaunay_triangulation(const std::vector<Point2>& nodes);

}  // namespace trapdem
