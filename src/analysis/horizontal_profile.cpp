#include "analysis/horizontal_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace trapdem {

TriangleField make_triangle_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                  const std::vector<double>& value) {
  if (value.size() != mesh.size()) {
    throw InputError("make_triangle_field: " + std::to_string(value.size()) + " values for " +
                     std::to_string(mesh.size()) + " triangles");
  }
  return {triangle_centroids(mesh, nodes), triangle_areas(mesh, nodes), value};
}

HorizontalProfile horizontal_profile(const TriangleField& field, double z_low, double z_high, double x_min,
                                     double x_max, double spacing, double kernel_width) {
  if (!(spacing > 0.0) || !(kernel_width > 0.0)) {
    throw InputError("horizontal_profile: spacing and kernel_width must be positive (m)");
  }
  struct Sample {
    double x, weight, value;
  };
  std::vector<Sample> slab;
  for (std::size_t t = 0; t < field.size(); ++t) {
    const Point2 c = field.centroid[t];
    if (c.z >= z_low && c.z < z_high && std::isfinite(field.value[t])) slab.push_back({c.x, field.area[t], field.value[t]});
  }
  std::sort(slab.begin(), slab.end(), [](const Sample& a, const Sample& b) { return a.x < b.x; });

  HorizontalProfile profile;
  const std::size_t n = x_max >= x_min ? static_cast<std::size_t>(std::floor((x_max - x_min) / spacing)) + 1 : 0;
  profile.x.resize(n);
  profile.value.resize(n);
  const double reach = 3.0 * kernel_width;
  const double inv_two_var = 1.0 / (2.0 * kernel_width * kernel_width);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = x_min + static_cast<double>(k) * spacing;
    auto it = std::lower_bound(slab.begin(), slab.end(), x - reach, [](const Sample& s, double v) { return s.x < v; });
    double sum_w = 0.0, sum_wv = 0.0;
    for (; it != slab.end() && it->x <= x + reach; ++it) {
      const double dx = it->x - x;
      const double w = it->weight * std::exp(-dx * dx * inv_two_var);  // Gaussian kernel, area weighted
      sum_w += w;
      sum_wv += w * it->value;
    }
    profile.x[k] = x;
    profile.value[k] = sum_w > 0.0 ? sum_wv / sum_w : std::numeric_limits<double>::quiet_NaN();
  }
  return profile;
}

std::size_t index_of_maximum(const HorizontalProfile& profile, double x_low, double x_high) {
  std::size_t best = profile.x.size();
  for (std::size_t k = 0; k < profile.x.size(); ++k) {
    if (profile.x[k] < x_low || profile.x[k] > x_high || !std::isfinite(profile.value[k])) continue;
    if (best == profile.x.size() || profile.value[k] > profile.value[best]) best = k;
  }
  return best;
}

double refined_peak_position(const HorizontalProfile& p, std::size_t peak) {
  if (peak == 0 || peak + 1 >= p.x.size()) return p.x[peak];
  const double a = p.value[peak - 1], b = p.value[peak], c = p.value[peak + 1];
  const double curvature = a - 2.0 * b + c;
  if (!std::isfinite(a) || !std::isfinite(c) || curvature >= 0.0) return p.x[peak];
  const double offset = std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);  // vertex of the parabola
  return p.x[peak] + offset * (p.x[1] - p.x[0]);
}

HalfMaximumCrossings half_maximum_crossings(const HorizontalProfile& p, std::size_t peak, double max_half_width) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double half = 0.5 * p.value[peak];
  const auto crossing = [&](int direction) {
    std::size_t k = peak;
    while (true) {
      const long next = static_cast<long>(k) + direction;
      if (next < 0 || next >= static_cast<long>(p.x.size())) return nan;
      const std::size_t j = static_cast<std::size_t>(next);
      if (!std::isfinite(p.value[j]) || std::abs(p.x[j] - p.x[peak]) > max_half_width) return nan;
      if (p.value[j] < half) {  // linear interpolation between k (above half) and j (below)
        const double f = (p.value[k] - half) / (p.value[k] - p.value[j]);
        return p.x[k] + f * (p.x[j] - p.x[k]);
      }
      k = j;
    }
  };
  return {crossing(-1), crossing(+1)};
}

double full_width_at_half_maximum(const HorizontalProfile& p, std::size_t peak, double max_half_width) {
  return half_maximum_crossings(p, peak, max_half_width).width();  // NaN if either side is NaN
}

}  // namespace trapdem
