#include "analysis/grid_field.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

void check_grid_memory(double width, double height, double spacing, const char* what) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InputError(fmt::format("{} {} m: expected a positive finite spacing", what, spacing));
  // Nodes per side as doubles: the count of a tiny spacing does not fit an integer.
  const double nodes = (std::floor(width / spacing) + 2.0) * (std::floor(height / spacing) + 2.0);
  const double bytes = nodes * double(sizeof(double));
  if (bytes > kMaxGridFieldBytes) {
    const double min_spacing = std::sqrt(width * height * double(sizeof(double)) / kMaxGridFieldBytes);
    throw InputError(fmt::format("{} {:g} m over {:.4g} x {:.4g} mm: {:.3g} nodes, {:.3g} bytes per field; expected at "
                                 "most {:.0f} GiB per field, a spacing of at least {:.2g} m",
                                 what, spacing, width * 1e3, height * 1e3, nodes, bytes,
                                 kMaxGridFieldBytes / (1024.0 * 1024.0 * 1024.0), min_spacing));
  }
}

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
  check_grid_memory(x_max - x_min, z_max - z_min, spacing, "grid spacing");
  GridSpec g;
  g.spacing = spacing;
  g.x0 = std::floor(x_min / spacing) * spacing;
  g.z0 = std::floor(z_min / spacing) * spacing;
  g.nx = static_cast<std::size_t>(std::ceil((x_max - g.x0) / spacing)) + 1;
  g.nz = static_cast<std::size_t>(std::ceil((z_max - g.z0) / spacing)) + 1;
  return g;
}

}  // namespace trapdem
