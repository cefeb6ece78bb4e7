// Contour lines by marching squares on analytic fields with known contour positions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "plot/axes.hpp"
#include "plot/marching_squares.hpp"

using namespace trapdem;
using namespace trapdem::plot;

namespace {

GridField sample(std::size_t nx, std::size_t nz, double h, double (*f)(double, double)) {
  GridField g;
  g.grid = {-0.5, -0.5, h, nx, nz};
  g.value.resize(nx * nz);
  for (std::size_t j = 0; j < nz; ++j) {
    for (std::size_t i = 0; i < nx; ++i) g.value[j * nx + i] = f(g.grid.x(i), g.grid.z(j));
  }
  return g;
}

}  // namespace

// f = x: linear interpolation is exact, so the contour at 0.123 is the vertical line x = 0.123
// from the bottom to the top of the grid, one open polyline. Tolerance 1e-12 (round-off).
TEST(MarchingSquares, LinearFieldGivesTheExactLine) {
  const GridField g = sample(51, 41, 0.025, [](double x, double) { return x; });
  const auto lines = contour_lines(g, 0.123);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FALSE(lines[0].closed);
  EXPECT_EQ(lines[0].points.size(), 41u);
  for (const Point2& p : lines[0].points) EXPECT_NEAR(p.x, 0.123, 1e-12);
  EXPECT_NEAR(lines[0].length(), 1.0, 1e-12);
}

// f = distance from the origin: the contour at r = 0.3 is one closed loop; linear interpolation
// of the distance along a cell edge of h = 0.0125 is off by at most h^2 / (8 r) ~ 7e-5.
TEST(MarchingSquares, CircleIsOneClosedLoopAtItsRadius) {
  const double h = 0.0125, r = 0.3;
  const GridField g = sample(81, 81, h, [](double x, double z) { return std::hypot(x, z); });
  const auto lines = contour_lines(g, r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].closed);
  double worst = 0.0;
  for (const Point2& p : lines[0].points) worst = std::max(worst, std::abs(std::hypot(p.x, p.z) - r));
  std::printf("[ measured ] circle contour radius error %.3g (tolerance %.3g)\n", worst, h * h / (8 * r));
  EXPECT_LE(worst, h * h / (8 * r));
  EXPECT_NEAR(lines[0].length(), 2 * M_PI * r, 0.01);
}

// Cells touching NaN are skipped: the line stops at the hole's edge, leaving two pieces.
TEST(MarchingSquares, NaNCellsInterruptTheLine) {
  GridField g = sample(21, 21, 0.05, [](double x, double) { return x; });
  for (std::size_t i = 0; i < 21; ++i) g.value[10 * 21 + i] = std::numeric_limits<double>::quiet_NaN();
  const auto lines = contour_lines(g, 0.01);
  EXPECT_EQ(lines.size(), 2u);
  for (const auto& l : lines) {
    for (const Point2& p : l.points) EXPECT_TRUE(p.z < -0.0 + 1e-12 || p.z > 0.05 - 1e-12);
  }
}

// A saddle (f = x z) at level 0 gives the two axes; no segment crosses a quadrant.
TEST(MarchingSquares, SaddleGivesTheTwoAxes) {
  const GridField g = sample(20, 20, 1.0 / 19.0, [](double x, double z) { return (x - 0.01) * (z - 0.013); });
  for (const auto& l : contour_lines(g, 0.0)) {
    for (const Point2& p : l.points) EXPECT_TRUE(std::abs(p.x - 0.01) < 1e-9 || std::abs(p.z - 0.013) < 1e-9);
  }
}

TEST(Axes, NiceTicks) {
  EXPECT_EQ(nice_ticks(0.0, 80.0, 8), (std::vector<double>{0, 10, 20, 30, 40, 50, 60, 70, 80}));
  EXPECT_EQ(nice_ticks(-7.0, 45.0, 6), (std::vector<double>{0, 10, 20, 30, 40}));
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(20.0, 10.0), "20");
}
