#pragma once
// The report's findings: one sentence per quantity saying how it changes over the study's cases, in
// the order the study lists them, computed from the measured values (never typed in).
#include <functional>
#include <string>
#include <vector>

#include "study/case_summary.hpp"
#include "study/replicate_statistics.hpp"

namespace trapdem {

// How `quantity` ("The band angle to the vertical") changes over the cases: falls or rises at every
// step, falls or rises overall but not at every step, ends about where it starts, or stays within
// `tolerance` (changes no larger than it count as no change: the measurement's resolution). NaN values
// are left out and named. `format` prints one value with its unit ("12.3°").
std::string describe_trend(const std::string& quantity, const std::vector<std::string>& labels,
                           const std::vector<double>& values, double tolerance,
                           const std::function<std::string(double)>& format);

// The same with each case's value a mean over its replicates (Spread). The trend rule: two cases
// differ only when their means differ by more than the larger of `tolerance` and the sum of their
// sample standard deviations (a case of one replicate adds no spread: its value stands alone).
// "falls/rises" needs the first and last case to differ so; "about the same" / "no trend beyond the
// seed-to-seed spread" says no two cases do. With a case of two or more replicates, values are
// written "mean ± sd" and the sentence says whether the change is beyond the seed-to-seed spread.
std::string describe_trend(const std::string& quantity, const std::vector<std::string>& labels,
                           const std::vector<Spread>& values, double tolerance,
                           const std::function<std::string(double)>& format);

// Whether the means of `a` and `b` differ beyond max(tolerance, sd_a + sd_b) (sd of a single
// replicate: 0). Missing values (n = 0) never differ.
bool differs_beyond_spread(const Spread& a, const Spread& b, double tolerance);

// Which cases' zone of influence is columnar and which elliptical (the analysis's classification).
std::string describe_shapes(const std::vector<CaseSummary>& cases);

// The sentences the report lists: the analysis' warnings, the band angles with their uncertainty,
// the mechanism metrics, the arching, the element test's angles (when run) and the sinkhole
// estimates; each trend with the rule above over the cases' replicates.
std::vector<std::string> study_findings(const std::vector<CaseEnsemble>& cases, double angle_of_draw_deg);
// Cases of one run each.
std::vector<std::string> study_findings(const std::vector<CaseSummary>& cases, double angle_of_draw_deg);

}  // namespace trapdem
