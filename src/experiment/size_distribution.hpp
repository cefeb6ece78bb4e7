#pragma once
// Particle sizes: a single size, uniform between two sizes, or a grading table (size against
// percent passing by mass, as a sieve analysis gives it: the seed paper's Figure 3).
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace trapdem {

class SizeDistribution {
 public:
  static SizeDistribution single(double diameter);
  static SizeDistribution uniform(double min_diameter, double max_diameter);
  // (diameter in m, percent passing by mass), sizes increasing, percent from 0 to 100.
  static SizeDistribution grading(std::vector<std::pair<double, double>> table, const std::string& where);

  // A diameter (m) drawn so that the mass fractions follow the distribution: for a grading,
  // the diameter at a uniformly drawn mass fraction, turned into a number fraction by weighting
  // with 1/d^3 (small particles are many per unit mass).
  double sample(std::mt19937_64& rng) const;
  double min_diameter() const { return min_; }
  double max_diameter() const { return max_; }
  double mean_diameter() const;  // number mean, m
  std::string describe() const;

 private:
  enum class Kind { single, uniform, grading } kind_ = Kind::single;
  double min_ = 0.0, max_ = 0.0;
  std::vector<std::pair<double, double>> table_;
  // For grading: the number-weighted cumulative distribution over fine bins.
  std::vector<double> bin_diameter_, bin_cumulative_;
};

}  // namespace trapdem
