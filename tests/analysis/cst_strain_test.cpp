// Constant strain triangles: exact for linear displacement fields, zero shear for rigid motion,
// the analytic gamma_max in simple shear. Compression positive throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/total_strain.hpp"
#include "analysis_test_support.hpp"

using namespace trapdem;
using test::displacements_of;
using test::report;

namespace {

// Round-off bound for strains from a CST over a 2 mm packing at 0.1 m from the origin: node
// coordinates carry ~1e-17 m of rounding, edges ~1e-3 m, so the gradient's relative error is
// ~1e-14 of the largest displacement gradient, and displacements up to 0.02 m spoil at most
// ~1e-16 m / 1e-3 m = 1e-13 in absolute terms (measured: up to 2e-14). 1e-12 leaves a margin
// and is still nine orders below the strains tested (1e-3 and up).
constexpr double round_off = 1e-12;

struct MaxError {
  double value = 0.0;
  void add(double e) { value = std::max(value, std::abs(e)); }
};

}  // namespace

TEST(CstStrain, UniformGradientGivesThatStrainOnEveryTriangle) {
  const auto s = test::make_specimen(0.0, 0.1, 0.0, 0.08, 1);
  ASSERT_GT(s.mesh.size(), 3000u);
  // u = t + G x with G = [[du/dx, du/dz], [dw/dx, dw/dz]] and a translation t.
  const double du_dx = 2e-3, du_dz = -3e-3, dw_dx = 1e-3, dw_dz = -4e-3;
  const auto u = displacements_of(s.nodes, [&](Point2 p) {
    return Point2{0.004 + du_dx * p.x + du_dz * p.z, -0.007 + dw_dx * p.x + dw_dz * p.z};
  });
  // Compression positive: e_xx = -du/dx, e_zz = -dw/dz, gamma_xz = -(du/dz + dw/dx).
  const double exx = -2e-3, ezz = 4e-3, gamma_xz = 2e-3;
  const double gamma_max = std::sqrt(36e-6 + 4e-6), volumetric = 2e-3;
  MaxError error;
  const auto strains = triangle_strains(s.mesh, s.nodes, u);
  for (const auto& e : strains) {
    error.add(e.exx - exx);
    error.add(e.ezz - ezz);
    error.add(e.gamma_xz - gamma_xz);
    error.add(maximum_shear_strain(e) - gamma_max);
    error.add(volumetric_strain(e) - volumetric);
  }
  report("uniform gradient, max strain error", error.value, round_off);
  EXPECT_LE(error.value, round_off);
}

TEST(CstStrain, RigidTranslationGivesNoStrain) {
  const auto s = test::make_specimen(0.0, 0.1, 0.0, 0.08, 2);
  const auto u = displacements_of(s.nodes, [](Point2) { return Point2{0.013, -0.021}; });
  MaxError error;
  for (const auto& e : triangle_strains(s.mesh, s.nodes, u)) {
    error.add(e.exx);
    error.add(e.ezz);
    error.add(e.gamma_xz);
  }
  report("rigid translation, max |strain|", error.value, round_off);
  EXPECT_LE(error.value, round_off);
}

// A rigid rotation by theta: du/dx = dw/dz = cos(theta) - 1, du/dz = -sin(theta), dw/dx = sin(theta).
// The small-strain shear parts cancel exactly (gamma_xz = 0, e_xx = e_zz), so gamma_max is zero
// up to round-off for ANY angle; what the rotation does leave is a spurious isotropic compression
// e_xx = e_zz = 1 - cos(theta) ~ theta^2 / 2, second order in the angle. Tolerances: gamma_max
// round-off; each normal strain within theta^2 / 2 (plus round-off) of zero, and exactly
// 1 - cos(theta) to round-off.
TEST(CstStrain, SmallRigidRotationGivesNoShearAndSecondOrderNormalStrain) {
  const auto s = test::make_specimen(0.0, 0.1, 0.0, 0.08, 3);
  for (const double theta : {1e-3, 1e-2, 0.1}) {
    const Point2 pivot{0.05, 0.0};
    const auto u = displacements_of(s.nodes, [&](Point2 p) {
      const Point2 r = p - pivot;
      return Point2{std::cos(theta) * r.x - std::sin(theta) * r.z - r.x,
                    std::sin(theta) * r.x + std::cos(theta) * r.z - r.z};
    });
    MaxError shear, normal_bound, normal_exact;
    for (const auto& e : triangle_strains(s.mesh, s.nodes, u)) {
      shear.add(maximum_shear_strain(e));
      normal_bound.add(std::max(std::abs(e.exx), std::abs(e.ezz)));
      normal_exact.add(e.exx - (1.0 - std::cos(theta)));
      normal_exact.add(e.ezz - (1.0 - std::cos(theta)));
    }
    report(("rotation " + std::to_string(theta) + " rad, max gamma_max").c_str(), shear.value, round_off);
    report("  max |e_xx - (1 - cos theta)|", normal_exact.value, round_off);
    EXPECT_LE(shear.value, round_off);
    EXPECT_LE(normal_bound.value, 0.5 * theta * theta + round_off);
    EXPECT_LE(normal_exact.value, round_off);
  }
}

// Simple shear u = gamma z, w = 0: e_xx = e_zz = 0, |gamma_xz| = gamma, so gamma_max = gamma;
// and simple shear along a direction at 30 degrees gives the same gamma_max (invariance).
TEST(CstStrain, SimpleShearGivesAnalyticMaximumShear) {
  const auto s = test::make_specimen(0.0, 0.1, 0.0, 0.08, 4);
  const double gamma = 0.01;
  const auto horizontal = displacements_of(s.nodes, [&](Point2 p) { return Point2{gamma * p.z, 0.0}; });
  const double a = 30.0 * std::numbers::pi / 180.0;
  const Point2 along{std::cos(a), std::sin(a)}, across{-std::sin(a), std::cos(a)};
  const auto inclined = displacements_of(s.nodes, [&](Point2 p) {
    const double n = p.x * across.x + p.z * across.z;  // distance across the shear direction
    return Point2{gamma * n * along.x, gamma * n * along.z};
  });
  MaxError error;
  for (const auto& e : triangle_strains(s.mesh, s.nodes, horizontal)) {
    error.add(maximum_shear_strain(e) - gamma);
    error.add(e.gamma_xz + gamma);  // compression positive: gamma_xz = -(du/dz) = -gamma
    error.add(volumetric_strain(e));
  }
  for (const auto& e : triangle_strains(s.mesh, s.nodes, inclined)) {
    error.add(maximum_shear_strain(e) - gamma);
    error.add(volumetric_strain(e));
  }
  report("simple shear, max error", error.value, round_off);
  EXPECT_LE(error.value, round_off);
}

TEST(CstStrain, CompressionIsPositive) {
  // Vertical shortening by 1 %: w = -0.01 z gives e_zz = +0.01 and e_vol = +0.01.
  const std::array<Point2, 3> node{Point2{0, 0}, Point2{0.002, 0}, Point2{0.001, 0.0017}};
  const std::array<Point2, 3> disp{Point2{0, 0}, Point2{0, 0}, Point2{0, -0.01 * 0.0017}};
  const PlaneStrain e = small_strain(cst_displacement_gradient(node, disp));
  EXPECT_NEAR(e.ezz, 0.01, 1e-15);
  EXPECT_NEAR(volumetric_strain(e), 0.01, 1e-15);
  EXPECT_NEAR(maximum_shear_strain(e), 0.01, 1e-15);
  // Clockwise node order gives the same gradient (the signed area and the sums both flip).
  const PlaneStrain f = small_strain(cst_displacement_gradient({node[0], node[2], node[1]}, {disp[0], disp[2], disp[1]}));
  EXPECT_NEAR(f.ezz, 0.01, 1e-15);
}

TEST(CstStrain, DegenerateTriangleGivesNaN) {
  const auto g = cst_displacement_gradient({Point2{0, 0}, Point2{1, 0}, Point2{2, 0}},
                                           {Point2{0, 0}, Point2{0, 1}, Point2{0, 0}});
  EXPECT_TRUE(std::isnan(g.du_dx));
}
