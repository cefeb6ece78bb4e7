#include "analysis/delaunay.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <utility>

namespace trapdem {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;

// Rotates the triple so the smallest index comes first; the cyclic order (orientation) is kept.
TriangleNodes canonical_rotation(TriangleNodes t) {
  const auto smallest = std::min_element(t.begin(), t.end());
  std::rotate(t.begin(), smallest, t.end());
  return t;
}
}  // namespace

TriangleMesh delaunay_triangulation(const std::vector<Point2>& nodes) {
  std::vector<std::pair<Kernel::Point_2, std::size_t>> points;
  points.reserve(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) points.emplace_back(Kernel::Point_2(nodes[k].x, nodes[k].z), k);

  Delaunay triangulation;
  triangulation.insert(points.begin(), points.end());  // spatially sorted insertion, keeps the info

  TriangleMesh mesh;
  if (triangulation.dimension() < 2) return mesh;
  mesh.triangles.reserve(triangulation.number_of_faces());
  for (const auto face : triangulation.finite_face_handles()) {
    // CGAL's finite faces are counter-clockwise.
    mesh.triangles.push_back(
        canonical_rotation({face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()}));
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  return mesh;
}

}  // namespace trapdem
