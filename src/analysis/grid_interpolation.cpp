#include "analysis/grid_interpolation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace trapdem {

namespace {

// Calls visit(index, barycentric weights) for every grid node inside triangle `corners`
// (boundary included, with a round-off margin so nodes on a shared edge are not lost).
template <class Visit>
void for_grid_nodes_in_triangle(const std::array<Point2, 3>& c, const GridSpec& grid, Visit&& visit) {
  const double two_area = twice_signed_area(c[0], c[1], c[2]);
  if (two_area == 0.0) return;
  const double x_lo = std::min({c[0].x, c[1].x, c[2].x}), x_hi = std::max({c[0].x, c[1].x, c[2].x});
  const double z_lo = std::min({c[0].z, c[1].z, c[2].z}), z_hi = std::max({c[0].z, c[1].z, c[2].z});
  const auto first = [&](double lo, double origin, std::size_t n) {
    const double k = std::ceil((lo - origin) / grid.spacing);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(n)));
  };
  const auto last = [&](double hi, double origin, std::size_t n) {  // one past the end
    const double k = std::floor((hi - origin) / grid.spacing) + 1.0;
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(n)));
  };
  const std::size_t i0 = first(x_lo, grid.x0, grid.nx), i1 = last(x_hi, grid.x0, grid.nx);
  const std::size_t j0 = first(z_lo, grid.z0, grid.nz), j1 = last(z_hi, grid.z0, grid.nz);
  constexpr double margin = -1e-12;
  for (std::size_t j = j0; j < j1; ++j) {
    for (std::size_t i = i0; i < i1; ++i) {
      const Point2 p{grid.x(i), grid.z(j)};
      // Barycentric coordinates: sub-triangle areas over the whole (signed, so orientation-free).
      const double l0 = twice_signed_area(p, c[1], c[2]) / two_area;
      const double l1 = twice_signed_area(c[0], p, c[2]) / two_area;
      const double l2 = 1.0 - l0 - l1;
      if (l0 >= margin && l1 >= margin && l2 >= margin) visit(j * grid.nx + i, std::array<double, 3>{l0, l1, l2});
    }
  }
}

GridField blank_field(const GridSpec& grid) {
  return {grid, std::vector<double>(grid.nx * grid.nz, std::numeric_limits<double>::quiet_NaN())};
}

}  // namespace

GridField interpolate_nodal_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                  const std::vector<double>& nodal_value, const GridSpec& grid) {
  if (nodal_value.size() != nodes.size()) {
    throw InputError("interpolate_nodal_field: " + std::to_string(nodal_value.size()) + " values for " +
                     std::to_string(nodes.size()) + " nodes");
  }
  GridField field = blank_field(grid);
  for (const auto& tri : mesh.triangles) {
    const double v[3] = {nodal_value[tri[0]], nodal_value[tri[1]], nodal_value[tri[2]]};
    for_grid_nodes_in_triangle(triangle_corners(tri, nodes), grid, [&](std::size_t k, const std::array<double, 3>& l) {
      field.value[k] = l[0] * v[0] + l[1] * v[1] + l[2] * v[2];
    });
  }
  return field;
}

GridField sample_triangle_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                const std::vector<double>& triangle_value, const GridSpec& grid) {
  if (triangle_value.size() != mesh.size()) {
    throw InputError("sample_triangle_field: " + std::to_string(triangle_value.size()) + " values for " +
                     std::to_string(mesh.size()) + " triangles");
  }
  GridField field = blank_field(grid);
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    for_grid_nodes_in_triangle(triangle_corners(mesh.triangles[t], nodes), grid,
                               [&](std::size_t k, const std::array<double, 3>&) { field.value[k] = triangle_value[t]; });
  }
  return field;
}

}  // namespace trapdem
