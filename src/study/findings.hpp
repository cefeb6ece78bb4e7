#pragma once
// The report's findings: one sentence per quantity saying how it changes over the study's cases, in
// the order the study lists them, computed from the measured values (never typed in).
#include <functional>
#include <string>
#include <vector>

#include "study/case_summary.hpp"

namespace trapdem {

// How `quantity` ("The band angle to the vertical") changes over the cases: falls or rises at every
// step, falls or rises overall but not at every step, ends about where it starts, or stays within
// `tolerance` (changes no larger than it count as no change: the measurement's resolution). NaN values
// are left out and named. `format` prints one value with its unit ("12.3°").
std::string describe_trend(const std::string& quantity, const std::vector<std::string>& labels,
                           const std::vector<double>& values, double tolerance,
                           const std::function<std::string(double)>& format);

// Which cases' zone of influence is columnar and which elliptical (the analysis's classification).
std::string describe_shapes(const std::vector<CaseSummary>& cases);

// The sentences the report lists: the mechanism metrics, the arching, and the sinkhole estimates.
std::vector<std::string> study_findings(const std::vector<CaseSummary>& cases, double angle_of_draw_deg);

}  // namespace trapdem
