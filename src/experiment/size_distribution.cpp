#include "experiment/size_distribution.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

SizeDistribution SizeDistribution::single(double d) {
  if (!(d > 0.0)) throw InputError(fmt::format("particle diameter {} m: expected a positive size", d));
  SizeDistribution s;
  s.kind_ = Kind::single;
  s.min_ = s.max_ = d;
  return s;
}

SizeDistribution SizeDistribution::uniform(double lo, double hi) {
  if (!(lo > 0.0) || !(hi >= lo))
    throw InputError(fmt::format("particle diameters {} .. {} m: expected 0 < min <= max", lo, hi));
  SizeDistribution s;
  s.kind_ = lo == hi ? Kind::single : Kind::uniform;
  s.min_ = lo;
  s.max_ = hi;
  return s;
}

SizeDistribution SizeDistribution::grading(std::vector<std::pair<double, double>> table, const std::string& where) {
  if (table.size() < 2) throw InputError(where + ": a grading needs at least two (size, percent passing) rows");
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto [d, pct] = table[k];
    if (!(d > 0.0)) throw InputError(fmt::format("{}: row {}: size {} m must be positive", where, k + 1, d));
    if (!(pct >= 0.0 && pct <= 100.0))
      throw InputError(fmt::format("{}: row {}: percent passing {} must lie in [0, 100]", where, k + 1, pct));
    if (k > 0 && !(d > table[k - 1].first && pct >= table[k - 1].second))
      throw InputError(fmt::format("{}: row {}: sizes must increase and percent passing must not decrease", where, k + 1));
  }
  if (table.front().second != 0.0 || table.back().second != 100.0)
    throw InputError(fmt::format("{}: the grading must start at 0 % and end at 100 % passing (got {} and {})", where,
                                 table.front().second, table.back().second));
  SizeDistribution s;
  s.kind_ = Kind::grading;
  s.table_ = std::move(table);
  s.min_ = s.table_.front().first;
  s.max_ = s.table_.back().first;
  // Number-weighted CDF on fine bins: within a table interval the mass is spread log-uniformly.
  const int bins_per_interval = 64;
  double cumulative = 0.0;
  for (std::size_t k = 1; k < s.table_.size(); ++k) {
    const double d0 = s.table_[k - 1].first, d1 = s.table_[k].first;
    const double mass = (s.table_[k].second - s.table_[k - 1].second) / 100.0;
    for (int b = 0; b < bins_per_interval; ++b) {
      const double d = d0 * std::pow(d1 / d0, (b + 0.5) / bins_per_interval);
      cumulative += mass / bins_per_interval / (d * d * d);
      s.bin_diameter_.push_back(d);
      s.bin_cumulative_.push_back(cumulative);
    }
  }
  for (double& c : s.bin_cumulative_) c /= cumulative;
  return s;
}

double SizeDistribution::sample(std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (kind_) {
    case Kind::single: return min_;
    case Kind::uniform: return min_ + (max_ - min_) * unit(rng);
    case Kind::grading: {
      const double u = unit(rng);
      const auto it = std::lower_bound(bin_cumulative_.begin(), bin_cumulative_.end(), u);
      const std::size_t k = std::min<std::size_t>(it - bin_cumulative_.begin(), bin_diameter_.size() - 1);
      return bin_diameter_[k];
    }
  }
  return min_;
}

double SizeDistribution::mean_diameter() const {
  switch (kind_) {
    case Kind::single: return min_;
    case Kind::uniform: return 0.5 * (min_ + max_);
    case Kind::grading: {
      double mean = 0.0, previous = 0.0;
      for (std::size_t k = 0; k < bin_diameter_.size(); ++k) {
        mean += (bin_cumulative_[k] - previous) * bin_diameter_[k];
        previous = bin_cumulative_[k];
      }
      return mean;
    }
  }
  return min_;
}

std::string SizeDistribution::describe() const {
  switch (kind_) {
    case Kind::single: return fmt::format("single size {:.4g} mm", min_ * 1e3);
    case Kind::uniform: return fmt::format("uniform {:.4g}-{:.4g} mm", min_ * 1e3, max_ * 1e3);
    case Kind::grading: return fmt::format("grading {:.4g}-{:.4g} mm ({} rows)", min_ * 1e3, max_ * 1e3, table_.size());
  }
  return "";
}

}  // namespace trapdem
