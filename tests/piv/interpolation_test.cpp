// Cubic B-spline interpolation and the first-order warp algebra.
#include <gtest/gtest.h>

#include <cmath>

#include "piv/bspline_image.hpp"
#include "piv/subset_warp.hpp"
#include "piv_test_support.hpp"

namespace trapdem {
namespace {

cv::Mat smooth_image(int w, int h) {
  cv::Mat m(h, w, CV_64F);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) m.at<double>(r, c) = 100.0 + 50.0 * std::sin(0.3 * c + 0.1) * std::cos(0.25 * r);
  return m;
}

TEST(BSplineImage, PassesThroughEveryPixel) {
  const cv::Mat m = smooth_image(40, 30);
  const BSplineImage s = make_bspline_image(m);
  double worst = 0.0;
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) worst = std::max(worst, std::abs(interpolate(s, c, r) - m.at<double>(r, c)));
  test::report("largest misfit at pixel centres (grey levels)", worst, 1e-9);
  EXPECT_LT(worst, 1e-9);
}

TEST(BSplineImage, ReproducesASmoothSignalBetweenPixels) {
  // Wavelengths of 21 and 25 px: the interpolant and its gradient follow the continuous function.
  const cv::Mat m = smooth_image(64, 64);
  const BSplineImage s = make_bspline_image(m);
  double worst_value = 0.0, worst_slope = 0.0;
  for (double y = 8.0; y < 56.0; y += 0.37)
    for (double x = 8.0; x < 56.0; x += 0.41) {
      const ValueAndGradient g = interpolate_with_gradient(s, x, y);
      const double f = 100.0 + 50.0 * std::sin(0.3 * x + 0.1) * std::cos(0.25 * y);
      const double fx = 50.0 * 0.3 * std::cos(0.3 * x + 0.1) * std::cos(0.25 * y);
      const double fy = -50.0 * 0.25 * std::sin(0.3 * x + 0.1) * std::sin(0.25 * y);
      worst_value = std::max(worst_value, std::abs(g.value - f));
      worst_slope = std::max({worst_slope, std::abs(g.dx - fx), std::abs(g.dy - fy)});
      EXPECT_NEAR(g.value, interpolate(s, x, y), 1e-12);
    }
  test::report("largest value error, amplitude 50 (grey levels)", worst_value, 0.05);
  test::report("largest gradient error, amplitude 15 (grey levels/px)", worst_slope, 0.1);
  EXPECT_LT(worst_value, 0.05);
  EXPECT_LT(worst_slope, 0.1);
}

TEST(BSplineImage, WholeImageIncludingItsEdgesCanBeInterpolated) {
  const cv::Mat m = smooth_image(12, 9);
  const BSplineImage s = make_bspline_image(m);
  EXPECT_TRUE(inside_interpolation_band(s, 0.0, 0.0));
  EXPECT_TRUE(inside_interpolation_band(s, 11.0, 8.0));
  EXPECT_FALSE(inside_interpolation_band(s, 11.01, 4.0));
  EXPECT_FALSE(inside_interpolation_band(s, 4.0, -0.01));
  EXPECT_NEAR(interpolate(s, 11.0, 8.0), m.at<double>(8, 11), 1e-9);
  EXPECT_NEAR(interpolate(s, 0.0, 0.0), m.at<double>(0, 0), 1e-9);
}

TEST(SubsetWarp, ComposingWithTheInverseOfItselfGivesIdentity) {
  WarpParameters p{1.5, -0.7, 0.02, -0.01, 0.03, 0.015};
  const WarpParameters dp = p;
  ASSERT_TRUE(compose_with_inverse(p, dp));
  for (double x : {p.u, p.v, p.ux, p.vx, p.uy, p.vy}) EXPECT_NEAR(x, 0.0, 1e-14);
}

TEST(SubsetWarp, InverseCompositionMatchesThePointMapping) {
  // W(p) o W(dp)^-1 applied to a point equals W(p) applied to W(dp)^-1 of the point.
  WarpParameters p{0.8, 0.3, 0.01, 0.02, -0.015, 0.005};
  const WarpParameters dp{0.1, -0.05, 0.002, -0.001, 0.003, 0.001};
  const WarpParameters original = p;
  ASSERT_TRUE(compose_with_inverse(p, dp));
  for (auto [dx, dy] : {std::pair{3.0, -7.0}, std::pair{-12.5, 9.5}}) {
    // q = W(dp)^-1 (dx, dy): solve W(dp) q = (dx, dy).
    const double a = 1 + dp.ux, b = dp.uy, c = dp.vx, d = 1 + dp.vy, det = a * d - b * c;
    const double rx = dx - dp.u, ry = dy - dp.v;
    const double qx = (d * rx - b * ry) / det, qy = (-c * rx + a * ry) / det;
    const auto expected = warp_offset(original, qx, qy);
    const auto got = warp_offset(p, dx, dy);
    EXPECT_NEAR(got[0], expected[0], 1e-12);
    EXPECT_NEAR(got[1], expected[1], 1e-12);
  }
}

TEST(SubsetWarp, NeighbourStartExtrapolatesByTheGradients) {
  const WarpParameters p{1.0, 2.0, 0.01, -0.02, 0.03, 0.04};
  const WarpParameters q = shifted_warp(p, 16.0, -16.0);
  EXPECT_DOUBLE_EQ(q.u, 1.0 + 0.01 * 16 - 0.03 * 16);
  EXPECT_DOUBLE_EQ(q.v, 2.0 - 0.02 * 16 - 0.04 * 16);
  EXPECT_DOUBLE_EQ(q.ux, p.ux);
  EXPECT_NEAR(update_norm(WarpParameters{0.0, 0.0, 0.001, 0.0, 0.0, 0.0}, 16.0), 0.016, 1e-15);
}

}  // namespace
}  // namespace trapdem
