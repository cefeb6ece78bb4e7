#include "analysis/settlement_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

struct Columns {
  double x_min = 0.0;
  double width = 0.0;
  std::size_t count = 0;
  std::size_t of(double x) const {
    const auto k = static_cast<std::size_t>(std::max(0.0, std::floor((x - x_min) / width)));
    return std::min(k, count - 1);
  }
};

Columns columns_spanning(const PointSet2& points, double column_width) {
  if (!(column_width > 0.0)) throw InputError("settlement profile: column_width must be positive (m)");
  if (points.size() == 0) throw InputError("settlement profile: no nodes");
  double lo = points.position[0].x, hi = lo;
  for (const auto& p : points.position) {
    lo = std::min(lo, p.x);
    hi = std::max(hi, p.x);
  }
  Columns c{lo, column_width, static_cast<std::size_t>(std::floor((hi - lo) / column_width)) + 1};
  return c;
}

SettlementProfile averaged(const Columns& columns, const std::vector<double>& sum, const std::vector<double>& count) {
  SettlementProfile profile;
  profile.x.resize(columns.count);
  profile.settlement.resize(columns.count);
  for (std::size_t k = 0; k < columns.count; ++k) {
    profile.x[k] = columns.x_min + (static_cast<double>(k) + 0.5) * columns.width;
    profile.settlement[k] = count[k] > 0 ? sum[k] / count[k] : nan_value;
  }
  return profile;
}

}  // namespace

SettlementProfile settlement_profile_in_slab(const PointSet2& points, double z_low, double z_high,
                                             double column_width) {
  const Columns columns = columns_spanning(points, column_width);
  std::vector<double> sum(columns.count, 0.0), count(columns.count, 0.0);
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Point2 p = points.position[n];
    if (p.z < z_low || p.z >= z_high) continue;
    const std::size_t k = columns.of(p.x);
    sum[k] += -points.displacement[n].z;  // settlement: downward positive
    count[k] += 1.0;
  }
  return averaged(columns, sum, count);
}

SettlementProfile surface_settlement_profile(const PointSet2& points, double column_width,
                                             double surface_layer_thickness) {
  const Columns columns = columns_spanning(points, column_width);
  std::vector<double> top(columns.count, -std::numeric_limits<double>::infinity());
  for (const auto& p : points.position) top[columns.of(p.x)] = std::max(top[columns.of(p.x)], p.z);
  std::vector<double> sum(columns.count, 0.0), count(columns.count, 0.0);
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Point2 p = points.position[n];
    const std::size_t k = columns.of(p.x);
    if (p.z < top[k] - surface_layer_thickness) continue;
    sum[k] += -points.displacement[n].z;
    count[k] += 1.0;
  }
  SettlementProfile profile = averaged(columns, sum, count);
  std::vector<double> tops;
  for (double t : top) if (std::isfinite(t)) tops.push_back(t);
  std::sort(tops.begin(), tops.end());
  profile.surface_z = tops.empty() ? nan_value : tops[tops.size() / 2];
  return profile;
}

SettlementStretch stretch_where_settlement_exceeds(const SettlementProfile& p, double x_centre, double threshold) {
  SettlementStretch stretch{x_centre, x_centre, false, false};
  if (p.x.empty()) return stretch;
  const double spacing = p.x.size() > 1 ? p.x[1] - p.x[0] : 1.0;
  const auto nearest = static_cast<long>(std::lround((x_centre - p.x[0]) / spacing));
  const auto start = static_cast<std::size_t>(std::clamp(nearest, 0L, static_cast<long>(p.x.size()) - 1));
  if (!(p.settlement[start] >= threshold)) return stretch;
  const auto edge = [&](int direction, bool& reaches_end) {
    std::size_t k = start;
    while (true) {
      const long next = static_cast<long>(k) + direction;
      if (next < 0 || next >= static_cast<long>(p.x.size())) {
        reaches_end = true;
        return p.x[k];
      }
      const auto j = static_cast<std::size_t>(next);
      if (std::isnan(p.settlement[j])) return p.x[k];
      if (p.settlement[j] < threshold) {  // linear crossing between k (above) and j (below)
        const double f = (p.settlement[k] - threshold) / (p.settlement[k] - p.settlement[j]);
        return p.x[k] + f * (p.x[j] - p.x[k]);
      }
      k = j;
    }
  };
  stretch.left = edge(-1, stretch.reaches_left_end);
  stretch.right = edge(+1, stretch.reaches_right_end);
  return stretch;
}

double width_where_settlement_exceeds(const SettlementProfile& p, double x_centre, double threshold) {
  return stretch_where_settlement_exceeds(p, x_centre, threshold).width();
}

EndSettlements end_settlements(const SettlementProfile& p) {
  EndSettlements ends{nan_value, nan_value};
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    if (std::isfinite(p.settlement[k])) {
      ends.left = p.settlement[k];
      break;
    }
  }
  for (std::size_t k = p.x.size(); k-- > 0;) {
    if (std::isfinite(p.settlement[k])) {
      ends.right = p.settlement[k];
      break;
    }
  }
  return ends;
}

}  // namespace trapdem
