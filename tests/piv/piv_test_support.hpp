#pragma once
// Shared helpers of the PIV tests: error statistics over the valid subsets, printed next to
// their tolerance so the test log shows the margin; the check that bad input is a clear error.
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "piv/displacement_fields.hpp"
#include "piv/piv_result.hpp"

namespace trapdem::test {

// Runs `f`, expects an InputError whose message contains `fragment`.
template <class F>
void expect_input_error(F f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected one mentioning '" << fragment << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << "message: " << e.what();
  }
}

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
