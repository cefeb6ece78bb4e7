// Incremental strain accumulated per triangle (White & Bolton 2004 style, updated geometry).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/incremental_strain.hpp"
#include "analysis/total_strain.hpp"
#include "analysis_test_support.hpp"

using namespace trapdem;
using test::report;

namespace {
constexpr double round_off = 1e-12;  // as in cst_strain_test.cpp: CST round-off on a 2 mm packing

std::vector<Point2> moved(const std::vector<Point2>& nodes, const std::function<Point2(Point2)>& map) {
  std::vector<Point2> out(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) out[k] = map(nodes[k]);
  return out;
}
}  // namespace

TEST(IncrementalStrain, OneIncrementEqualsTotalStrain) {
  const auto s = test::make_specimen(0.0, 0.05, 0.0, 0.05, 5);
  const auto current = moved(s.nodes, [](Point2 p) { return Point2{p.x + 0.01 * p.z + 1e-3, p.z - 0.02 * p.z}; });
  const auto sum = accumulated_incremental_strain(s.mesh, {s.nodes, current});
  const auto total = triangle_strains(s.mesh, s.nodes, point_set_between(s.nodes, current).displacement);
  ASSERT_EQ(sum.increments, 1u);
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    ASSERT_NEAR(sum.strain[t].exx, total[t].exx, round_off);
    ASSERT_NEAR(sum.strain[t].ezz, total[t].ezz, round_off);
    ASSERT_NEAR(sum.strain[t].gamma_xz, total[t].gamma_xz, round_off);
    ASSERT_NEAR(sum.max_shear[t], maximum_shear_strain(total[t]), round_off);
  }
}

// Simple shear u = gamma z applied in 20 equal steps: heights never change, so each step's
// gradient over the updated (sheared) triangle is exactly du/dz = gamma / 20, and the sums are
// gamma_xz = -gamma (compression positive) and cumulative gamma_max = gamma, to round-off.
TEST(IncrementalStrain, SimpleShearInStepsAccumulatesToTheTotal) {
  const auto s = test::make_specimen(0.0, 0.05, 0.0, 0.05, 6);
  const double gamma = 0.2;
  const int steps = 20;
  std::vector<std::vector<Point2>> series;
  for (int k = 0; k <= steps; ++k) {
    const double g = gamma * k / steps;
    series.push_back(moved(s.nodes, [&](Point2 p) { return Point2{p.x + g * p.z, p.z}; }));
  }
  const auto sum = accumulated_incremental_strain(s.mesh, series);
  double error = 0.0;
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    error = std::max({error, std::abs(sum.strain[t].gamma_xz + gamma), std::abs(sum.max_shear[t] - gamma),
                      std::abs(sum.strain[t].exx), std::abs(sum.strain[t].ezz)});
  }
  report("simple shear in 20 steps, max error", error, round_off);
  EXPECT_LE(error, round_off);
}

// A large rigid rotation (0.5 rad) in 100 steps: the total small strain shows a spurious
// compression e_vol = 2 (1 - cos 0.5) = 0.245, the accumulated increments only
// 100 * 2 (1 - cos 0.005) = 0.0025 (each step's error is second order in its small angle), and
// gamma_max stays zero in both. Tolerance: round-off on each of the 100 sums.
TEST(IncrementalStrain, LargeRotationInStepsKeepsSpuriousStrainSmall) {
  const auto s = test::make_specimen(0.0, 0.05, 0.0, 0.05, 8);
  const double theta = 0.5;
  const int steps = 100;
  std::vector<std::vector<Point2>> series;
  for (int k = 0; k <= steps; ++k) {
    const double a = theta * k / steps;
    series.push_back(moved(s.nodes, [&](Point2 p) {
      return Point2{std::cos(a) * p.x - std::sin(a) * p.z, std::sin(a) * p.x + std::cos(a) * p.z};
    }));
  }
  const auto sum = accumulated_incremental_strain(s.mesh, series);
  const auto total = triangle_strains(s.mesh, s.nodes, point_set_between(s.nodes, series.back()).displacement);
  const double expected_incremental = steps * 2.0 * (1.0 - std::cos(theta / steps));
  double error = 0.0;
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    EXPECT_NEAR(volumetric_strain(total[t]), 2.0 * (1.0 - std::cos(theta)), round_off);
    error = std::max({error, std::abs(volumetric_strain(sum.strain[t]) - expected_incremental), sum.max_shear[t],
                      maximum_shear_strain(total[t])});
  }
  report("rotation 0.5 rad in 100 steps, max error", error, steps * round_off);
  EXPECT_LE(error, steps * round_off);
}

TEST(IncrementalStrain, MismatchedSizesThrow) {
  TriangleMesh mesh;
  EXPECT_THROW(incremental_strains(mesh, {{0, 0}}, {}), std::runtime_error);
  auto sum = start_accumulation(2);
  EXPECT_THROW(accumulate_increment(sum, std::vector<PlaneStrain>(3)), std::runtime_error);
}
