#include "analysis/triangle_filter.hpp"

#include "core/errors.hpp"

namespace trapdem {

FilteredMesh filter_triangles(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                              const TriangleFilterSettings& settings) {
  if (!(settings.mean_diameter > 0.0)) {
    throw InputError("filter_triangles: mean_diameter must be positive (m)");
  }
  const double max_edge = settings.max_edge_in_diameters * settings.mean_diameter;
  FilteredMesh result;
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const auto corners = triangle_corners(mesh.triangles[t], nodes);
    if (longest_edge(corners) > max_edge) {
      ++result.dropped_long_edge;
      result.dropped.triangles.push_back(mesh.triangles[t]);
    } else if (smallest_angle_deg(corners) < settings.min_angle_deg ||
               radius_ratio(corners) > settings.max_radius_ratio) {
      ++result.dropped_sliver;
      result.dropped.triangles.push_back(mesh.triangles[t]);
    } else {
      result.mesh.triangles.push_back(mesh.triangles[t]);
      result.source_index.push_back(t);
    }
  }
  return result;
}

}  // namespace trapdem
