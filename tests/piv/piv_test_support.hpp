#pragma once
// Shared helpers of the PIV tests: error statistics over the valid subsets, printed next to
// their tolerance so the test log shows the margin.
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "piv/displacement_fields.hpp"
#include "piv/piv_result.hpp"

namespace trapdem::test {

struct ErrorStatistics {
  double mean = 0.0;  // systematic error, px
  double std = 0.0;   // standard deviation, px
  double max_abs = 0.0;
  std::size_t count = 0;
};

inline ErrorStatistics statistics(const std::vector<double>& e) {
  ErrorStatistics s;
  s.count = e.size();
  if (e.empty()) return s;
  for (double x : e) s.mean += x;
  s.mean /= static_cast<double>(e.size());
  for (double x : e) {
    s.std += (x - s.mean) * (x - s.mean);
    s.max_abs = std::max(s.max_abs, std::abs(x));
  }
  s.std = std::sqrt(s.std / static_cast<double>(e.size()));
  return s;
}

// Errors of u and v of the valid subsets of image k against the prescribed total field.
inline std::pair<std::vector<double>, std::vector<double>> displacement_errors(
    const PivResult& r, std::size_t k, const DisplacementField& truth,
    const std::function<bool(cv::Point2d)>& include = {}) {
  std::vector<double> eu, ev;
  for (std::size_t i = 0; i < r.grid.size(); ++i) {
    const auto& m = r.image[k].subset[i];
    if (!m.is_valid()) continue;
    if (include && !include(r.grid.centre[i])) continue;
    const cv::Point2d t = truth(r.grid.centre[i]);
    eu.push_back(m.u - t.x);
    ev.push_back(m.v - t.y);
  }
  return {eu, ev};
}

inline void report(const char* what, double measured, double tolerance) {
  std::printf("[ measured ] %s: %.3g (tolerance %.3g)\n", what, measured, tolerance);
}

}  // namespace trapdem::test
