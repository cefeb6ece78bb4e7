// The Gaussian smoothing of a grid field (analysis/field_smoothing.hpp), which smooths a stored
// field_history.h5 layer as the analysis smoothed the triangles: the formula by brute force, a
// constant kept constant up to NaN holes and edges, a ridge widened as Gaussians convolve.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "analysis/field_smoothing.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

GridField grid_of(std::size_t nx, std::size_t nz, double spacing, double value) {
  GridField f;
  f.grid = GridSpec{0.01, -0.02, spacing, nx, nz};
  f.value.assign(nx * nz, value);
  return f;
}

// v_s(i, j) = sum w v / sum w over the finite nodes within 3 L, w = exp(-r^2 / (2 L^2)): every node
// against every node, no kernel table.
double brute_force(const GridField& f, std::size_t i, std::size_t j, double length) {
  double sum_w = 0.0, sum_wv = 0.0;
  for (std::size_t jj = 0; jj < f.grid.nz; ++jj)
    for (std::size_t ii = 0; ii < f.grid.nx; ++ii) {
      const double v = f.at(ii, jj);
      const double dx = f.grid.x(ii) - f.grid.x(i), dz = f.grid.z(jj) - f.grid.z(j);
      const double r2 = dx * dx + dz * dz;
      if (!std::isfinite(v) || r2 > 9.0 * length * length * (1.0 + 1e-12)) continue;
      const double w = std::exp(-r2 / (2.0 * length * length));
      sum_w += w;
      sum_wv += w * v;
    }
  return sum_wv / sum_w;
}

}  // namespace

TEST(GridSmoothing, EachNodeIsTheNormalisedGaussianAverageOfItsFiniteNeighbours) {
  const double d = 0.002;
  GridField f = grid_of(23, 17, d, 0.0);
  for (std::size_t j = 0; j < f.grid.nz; ++j)
    for (std::size_t i = 0; i < f.grid.nx; ++i) f.value[j * f.grid.nx + i] = std::sin(0.7 * i) + 0.3 * j + 0.01 * i * j;
  f.value[5 * f.grid.nx + 6] = kNaN;  // a hole and a missing corner
  for (std::size_t i = 18; i < 23; ++i) f.value[16 * f.grid.nx + i] = kNaN;
  for (const double length : {0.7 * d, 2.0 * d, 3.3 * d}) {
    const GridField s = smooth_grid_field(f, length);
    for (const auto& [i, j] : {std::pair<std::size_t, std::size_t>{0, 0}, {6, 4}, {7, 5}, {22, 15}, {11, 8}, {17, 16}})
      EXPECT_NEAR(s.at(i, j), brute_force(f, i, j, length), 1e-12) << "node " << i << ", " << j << ", L = " << length;
    EXPECT_TRUE(std::isnan(s.at(6, 5)));
    EXPECT_TRUE(std::isnan(s.at(20, 16)));
  }
}

// A constant stays constant at the edges and beside holes (the average is normalised over the
// finite nodes only); L = 0 is the identity; a negative or infinite length is an input error.
TEST(GridSmoothing, AConstantStaysConstantAndZeroLengthIsTheIdentity) {
  GridField f = grid_of(30, 20, 0.001, 0.25);
  for (std::size_t j = 8; j < 12; ++j) f.value[j * f.grid.nx + 14] = kNaN;
  const GridField s = smooth_grid_field(f, 0.002);
  for (std::size_t k = 0; k < s.value.size(); ++k) {
    if (std::isnan(f.value[k])) EXPECT_TRUE(std::isnan(s.value[k])) << k;
    else EXPECT_NEAR(s.value[k], 0.25, 1e-15) << k;
  }
  f.value[3] = 7.0;
  const GridField same = smooth_grid_field(f, 0.0);
  ASSERT_EQ(same.value.size(), f.value.size());
  for (std::size_t k = 0; k < f.value.size(); ++k)  // NaN stays NaN (and NaN != NaN)
    EXPECT_TRUE(same.value[k] == f.value[k] || (std::isnan(same.value[k]) && std::isnan(f.value[k]))) << k;
  EXPECT_THROW(smooth_grid_field(f, -0.001), InputError);
  EXPECT_THROW(smooth_grid_field(f, std::numeric_limits<double>::infinity()), InputError);
}

// A vertical Gaussian ridge of full width at half maximum W, smoothed at L, has the full width
// sqrt(W^2 + (2.355 L)^2) (Gaussians convolve; 2.355 = 2 sqrt(2 ln 2)). The kernel cut at 3 L
// leaves out 1.1 % of its weight, which narrows the result by well under 1 %; the width is read
// between nodes by linear interpolation at a spacing of W / 20: 1 %.
TEST(GridSmoothing, ARidgeWidensAsGaussiansConvolve) {
  const double spacing = 0.0002, W = 20 * spacing, L = 10 * spacing;
  const double fwhm_per_sigma = 2.0 * std::sqrt(2.0 * std::log(2.0));
  GridField f = grid_of(301, 61, spacing, 0.0);
  const double centre = f.grid.x(150), sigma = W / fwhm_per_sigma;
  for (std::size_t j = 0; j < f.grid.nz; ++j)
    for (std::size_t i = 0; i < f.grid.nx; ++i) {
      const double u = f.grid.x(i) - centre;
      f.value[j * f.grid.nx + i] = std::exp(-u * u / (2.0 * sigma * sigma));
    }
  const GridField s = smooth_grid_field(f, L);
  const std::size_t row = 30;
  const double peak = s.at(150, row);
  // The right half-maximum crossing, interpolated between the two nodes around it.
  std::size_t i = 150;
  while (s.at(i + 1, row) > 0.5 * peak) ++i;
  const double a = s.at(i, row), b = s.at(i + 1, row);
  const double half_width = f.grid.x(i) + (a - 0.5 * peak) / (a - b) * spacing - centre;
  const double expected = std::sqrt(W * W + fwhm_per_sigma * L * fwhm_per_sigma * L);
  EXPECT_NEAR(2.0 * half_width, expected, 0.01 * expected);
}
