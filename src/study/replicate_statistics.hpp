#pragma once
// A case's replicates (one run per packing seed) in numbers: each metric's mean and spread, the
// case's summary as the replicates' means, and the mean ground reaction curve. The spread is the
// sample standard deviation (n - 1 in the denominator) and the range min..max; a single replicate
// has no spread (sd NaN, n = 1). docs/study.md states how the report and the findings use them.
#include <cstddef>
#include <functional>
#include <vector>

#include "core/json.hpp"
#include "study/case_summary.hpp"

namespace trapdem {

struct Spread {
  std::size_t n = 0;                   // finite values
  double mean = kMissing, sd = kMissing, min = kMissing, max = kMissing;
  bool has_sd() const { return n >= 2; }
};

// Mean, sample standard deviation, min and max of the finite values (NaN ones are left out).
Spread spread_of(const std::vector<double>& values);
// The spread with every value multiplied by `factor` (> 0): e.g. a width over B.
Spread scaled(const Spread& s, double factor);
Json to_json(const Spread& s);         // {n, mean, sd, min, max}, NaN as null

// A case with its replicates.
struct CaseEnsemble {
  CaseSummary mean;                    // combine_replicates(replicates)
  std::vector<CaseSummary> replicates; // in seed order; those that could be analysed
  // The spread over the replicates of one quantity.
  Spread spread(const std::function<double(const CaseSummary&)>& get) const;
  Spread spread(double CaseSummary::*field) const;
};

// The case's summary from its replicates: a single one as it is; else every metric the mean of the
// replicates that measured it, the shape the replicates' own (analysis/mechanism_shape.hpp) where
// they agree, else "mixed (k of n columnar)", the sinkhole classes from the mean diameters, the ground reaction
// curve the mean curve, the costs summed (particle-steps per second: their total over the total
// time). Warnings stay with each replicate.
CaseSummary combine_replicates(const std::vector<CaseSummary>& replicates);
// The replicates' shapes ("columnar", "elliptical", "unknown" or empty) combined: the common one of
// those known, "mixed (k of n columnar)" where they differ, "unknown" where none is known.
std::string combined_shape(const std::vector<CaseSummary>& replicates);
CaseEnsemble make_ensemble(std::vector<CaseSummary> replicates);

// The mean of several curves y_k(x_k) on the first curve's x, as far as the shortest one reaches
// (linear interpolation between each curve's points; x ascending in each).
void mean_curve(const std::vector<std::vector<double>>& xs, const std::vector<std::vector<double>>& ys,
                std::vector<double>& x_out, std::vector<double>& y_out);

}  // namespace trapdem
