#include "analysis/field_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

void check_smoothing_length(double length) {
  if (!(length >= 0.0) || !std::isfinite(length)) {
    throw InputError(fmt::format("strain smoothing length {} m: expected a finite length >= 0", length));
  }
}

}  // namespace

TriangleField smooth_triangle_field(const TriangleField& field, double length) {
  check_smoothing_length(length);
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

GridField smooth_grid_field(const GridField& field, double length) {
  check_smoothing_length(length);
  const GridSpec& g = field.grid;
  if (length == 0.0 || field.value.empty() || !(g.spacing > 0.0)) return field;
  // The kernel's weights on the node offsets within 3 L (the triangle smoothing's cut-off).
  const double reach = 3.0 * length;
  // Nodes at exactly 3 L count, as the triangles' do (reach / spacing is often a whole number that
  // the division leaves a rounding below it).
  const double slack = 1.0 + 1e-12;
  const auto half = static_cast<std::ptrdiff_t>(std::floor(reach / g.spacing * slack));
  const double inv_two_var = 1.0 / (2.0 * length * length);
  struct Offset {
    std::ptrdiff_t di, dj;
    double weight;
  };
  std::vector<Offset> kernel;
  for (std::ptrdiff_t dj = -half; dj <= half; ++dj)
    for (std::ptrdiff_t di = -half; di <= half; ++di) {
      const double r2 = static_cast<double>(di * di + dj * dj) * g.spacing * g.spacing;
      if (r2 <= reach * reach * slack) kernel.push_back({di, dj, std::exp(-r2 * inv_two_var)});
    }
  GridField smoothed = field;
  const auto nx = static_cast<std::ptrdiff_t>(g.nx), nz = static_cast<std::ptrdiff_t>(g.nz);
  for (std::ptrdiff_t j = 0; j < nz; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      if (!std::isfinite(field.value[static_cast<std::size_t>(j * nx + i)])) continue;
      double sum_w = 0.0, sum_wv = 0.0;
      for (const Offset& o : kernel) {
        const std::ptrdiff_t ii = i + o.di, jj = j + o.dj;
        if (ii < 0 || jj < 0 || ii >= nx || jj >= nz) continue;
        const double v = field.value[static_cast<std::size_t>(jj * nx + ii)];
        if (!std::isfinite(v)) continue;
        sum_w += o.weight;
        sum_wv += o.weight * v;
      }
      smoothed.value[static_cast<std::size_t>(j * nx + i)] = sum_wv / sum_w;  // the node itself has weight 1
    }
  return smoothed;
}

}  // namespace trapdem
