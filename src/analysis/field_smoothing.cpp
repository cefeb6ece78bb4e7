#include "analysis/field_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

TriangleField smooth_triangle_field(const TriangleField& field, double length) {
  if (!(length >= 0.0) || !std::isfinite(length)) {
    throw InputError(fmt::format("strain smoothing length {} m: expected a finite length >= 0", length));
  }
  if (length == 0.0 || field.size() == 0) return field;
  // Buckets of one cut-off radius (3 L): a triangle's neighbours lie in the 3 x 3 buckets around it.
  const double reach = 3.0 * length;
  double x_min = field.centroid[0].x, x_max = x_min, z_min = field.centroid[0].z, z_max = z_min;
  for (const auto& c : field.centroid) {
    x_min = std::min(x_min, c.x);
    x_max = std::max(x_max, c.x);
    z_min = std::min(z_min, c.z);
    z_max = std::max(z_max, c.z);
  }
  const auto nx = static_cast<std::size_t>(std::floor((x_max - x_min) / reach)) + 1;
  const auto nz = static_cast<std::size_t>(std::floor((z_max - z_min) / reach)) + 1;
  const auto bucket_x = [&](double x) { return std::min(nx - 1, static_cast<std::size_t>((x - x_min) / reach)); };
  const auto bucket_z = [&](double z) { return std::min(nz - 1, static_cast<std::size_t>((z - z_min) / reach)); };
  // Counting sort of the finite triangles into buckets (CSR).
  std::vector<std::size_t> start(nx * nz + 1, 0), members;
  for (std::size_t t = 0; t < field.size(); ++t) {
    if (std::isfinite(field.value[t])) ++start[bucket_z(field.centroid[t].z) * nx + bucket_x(field.centroid[t].x) + 1];
  }
  for (std::size_t b = 0; b < nx * nz; ++b) start[b + 1] += start[b];
  members.resize(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < field.size(); ++t) {
    if (std::isfinite(field.value[t])) {
      members[fill[bucket_z(field.centroid[t].z) * nx + bucket_x(field.centroid[t].x)]++] = t;
    }
  }

  TriangleField smoothed = field;
  const double inv_two_var = 1.0 / (2.0 * length * length);
  const double reach2 = reach * reach;
  for (std::size_t t = 0; t < field.size(); ++t) {
    if (!std::isfinite(field.value[t])) continue;
    const Point2 c = field.centroid[t];
    const std::size_t bx = bucket_x(c.x), bz = bucket_z(c.z);
    double sum_w = 0.0, sum_wv = 0.0;
    for (std::size_t jz = bz == 0 ? 0 : bz - 1; jz <= std::min(nz - 1, bz + 1); ++jz) {
      for (std::size_t jx = bx == 0 ? 0 : bx - 1; jx <= std::min(nx - 1, bx + 1); ++jx) {
        const std::size_t b = jz * nx + jx;
        for (std::size_t m = start[b]; m < start[b + 1]; ++m) {
          const std::size_t s = members[m];
          const double dx = field.centroid[s].x - c.x, dz = field.centroid[s].z - c.z;
          const double r2 = dx * dx + dz * dz;
          if (r2 > reach2) continue;
          const double w = field.area[s] * std::exp(-r2 * inv_two_var);
          sum_w += w;
          sum_wv += w * field.value[s];
        }
      }
    }
    smoothed.value[t] = sum_wv / sum_w;  // sum_w > 0: the triangle itself is within reach
  }
  return smoothed;
}

}  // namespace trapdem
