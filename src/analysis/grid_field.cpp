#include "analysis/grid_field.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace trapdem {

GridSpec grid_covering(const std::vector<Point2>& nodes, double spacing) {
  if (!(spacing > 0.0)) throw InputError("grid_covering: spacing must be positive (m)");
  if (nodes.empty()) throw InputError("grid_covering: no nodes");
  double x_min = nodes[0].x, x_max = nodes[0].x, z_min = nodes[0].z, z_max = nodes[0].z;
  for (const auto& p : nodes) {
    x_min = std::min(x_min, p.x);
    x_max = std::max(x_max, p.x);
    z_min = std::min(z_min, p.z);
    z_max = std::max(z_max, p.z);
  }
  GridSpec g;
  g.spacing = spacing;
  g.x0 = std::floor(x_min / spacing) * spacing;
  g.z0 = std::floor(z_min / spacing) * spacing;
  g.nx = static_cast<std::size_t>(std::ceil((x_max - g.x0) / spacing)) + 1;
  g.nz = static_cast<std::size_t>(std::ceil((z_max - g.z0) / spacing)) + 1;
  return g;
}

}  // namespace trapdem
