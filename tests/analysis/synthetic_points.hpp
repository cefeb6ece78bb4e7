#pragma once
// Synthetic particle centres for the analysis tests: a hexagonal (densest 2-D) lattice of
// spacing d with every point moved by a random offset, like the centres of a dense packing of
// discs of diameter d seen through the glass. Seeded, so every run sees the same set.
#include <cmath>
#include <random>
#include <vector>

#include "analysis/point_set.hpp"

namespace trapdem::test {

inline std::vector<Point2> jittered_hex_lattice(double x_min, double x_max, double z_min, double z_max,
                                                double spacing, double jitter_fraction, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-jitter_fraction * spacing, jitter_fraction * spacing);
  std::vector<Point2> points;
  const double row_height = spacing * std::sqrt(3.0) / 2.0;
  int row = 0;
  for (double z = z_min; z <= z_max + 1e-12; z += row_height, ++row) {
    const double shift = (row % 2) ? 0.5 * spacing : 0.0;
    for (double x = x_min + shift; x <= x_max + 1e-12; x += spacing) {
      points.push_back({x + offset(rng), z + offset(rng)});
    }
  }
  return points;
}

}  // namespace trapdem::test
