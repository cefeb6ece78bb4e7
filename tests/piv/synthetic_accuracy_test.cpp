// Accuracy targets of issue 5 on synthetic speckle, 32 px subsets, no noise.
#include <gtest/gtest.h>

#include <cmath>

#include "piv/piv_strain.hpp"
#include "piv/pixel_to_model.hpp"
#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"
#include "piv_test_support.hpp"

namespace trapdem {
namespace {

using test::report;
using test::statistics;

PivSettings default_settings() {
  PivSettings s;
  s.subset_size = 32;
  s.step = 16;
  return s;
}

// Sub-pixel rigid shifts 0.1 ... 0.9 px along x and y (diagonal): systematic error (mean) and
// standard deviation over the subsets each < 0.01 px, for every shift.
TEST(PivAccuracy, SubPixelRigidShiftErrorBelowOneHundredthPixel) {
  SpeckleSettings speckle;
  std::vector<DisplacementField> fields;
  for (int i = 1; i <= 9; ++i) fields.push_back(rigid_shift(0.1 * i, 0.05 * i));
  const auto images = synthesize_speckle_sequence(speckle, fields);
  double worst_mean = 0.0, worst_std = 0.0;
  for (std::size_t k = 1; k < images.size(); ++k) {
    const PivResult r = run_piv(std::vector<cv::Mat>{images[0], images[k]}, default_settings());
    const auto [eu, ev] = test::displacement_errors(r, 1, fields[k - 1]);
    // The last column and row leave the image (a positive shift moves them past the edge).
    ASSERT_GE(eu.size(), static_cast<std::size_t>((r.grid.columns - 1) * (r.grid.rows - 1)));
    for (const auto& e : {statistics(eu), statistics(ev)}) {
      worst_mean = std::max(worst_mean, std::abs(e.mean));
      worst_std = std::max(worst_std, e.std);
    }
    std::printf("shift %.2f, %.3f px: u error mean %.4f std %.4f; v error mean %.4f std %.4f (%zu subsets)\n",
                fields[k - 1]({0, 0}).x, fields[k - 1]({0, 0}).y, statistics(eu).mean, statistics(eu).std,
                statistics(ev).mean, statistics(ev).std, eu.size());
  }
  report("worst systematic error (px)", worst_mean, 0.01);
  report("worst standard deviation (px)", worst_std, 0.01);
  EXPECT_LT(worst_mean, 0.01);
  EXPECT_LT(worst_std, 0.01);
}

}  // namespace
}  // namespace trapdem

namespace trapdem {
namespace {

// Mean of a per-subset quantity over the valid subsets of image 1 -> 2.
double mean_over_valid(const PivResult& r, const std::function<double(const SubsetMeasurement&)>& f) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& m : r.image[1].subset)
    if (m.is_valid()) {
      sum += f(m);
      ++n;
    }
  return n ? sum / static_cast<double>(n) : std::nan("");
}

// 1 % uniform strain (tension along x, compression along y): the subset gradients and the
// constant strain triangles of the analysis module both give it within 2 % of its value.
TEST(PivAccuracy, UniformStrainOfOnePercentWithinTwoPercent) {
  SpeckleSettings speckle;
  const double exx = 0.01, eyy = -0.01;
  const auto images = synthesize_speckle_sequence(speckle, {uniform_strain(exx, eyy, {128.0, 128.0})});
  const PivResult r = run_piv(images, default_settings());
  EXPECT_GE(count_valid(r, 1), static_cast<std::size_t>((r.grid.columns - 2) * (r.grid.rows - 2)));

  const double ux = mean_over_valid(r, [](const SubsetMeasurement& m) { return m.relative.ux; });
  const double vy = mean_over_valid(r, [](const SubsetMeasurement& m) { return m.relative.vy; });
  report("IC-GN du/dx relative error", std::abs(ux - exx) / exx, 0.02);
  report("IC-GN dv/dy relative error", std::abs(vy - eyy) / std::abs(eyy), 0.02);
  EXPECT_NEAR(ux, exx, 0.02 * exx);
  EXPECT_NEAR(vy, eyy, 0.02 * std::abs(eyy));

  // Through the analysis module: model x = x px, z = -y px; compression positive, so
  // e_xx = -du/dx = -0.01 and e_zz = -dw/dz = -dv/dy = +0.01.
  const PivStrainField f = piv_total_strain(r, 1, scale_transform(1.0));
  ASSERT_GT(f.strain.size(), 100u);
  double sxx = 0.0, szz = 0.0;
  for (const auto& e : f.strain) {
    sxx += e.exx;
    szz += e.ezz;
  }
  sxx /= static_cast<double>(f.strain.size());
  szz /= static_cast<double>(f.strain.size());
  report("CST e_xx relative error", std::abs(sxx + exx) / exx, 0.02);
  report("CST e_zz relative error", std::abs(szz + eyy) / std::abs(eyy), 0.02);
  EXPECT_NEAR(sxx, -exx, 0.02 * exx);
  EXPECT_NEAR(szz, -eyy, 0.02 * std::abs(eyy));
}

// Simple shear gamma = du/dy = 2 %: recovered by the subset gradients and as gamma_max of the
// constant strain triangles, within 2 %; the normal strains stay near zero.
TEST(PivAccuracy, SimpleShearRecovered) {
  SpeckleSettings speckle;
  const double gamma = 0.02;
  const auto images = synthesize_speckle_sequence(speckle, {simple_shear(gamma, {128.0, 128.0})});
  const PivResult r = run_piv(images, default_settings());
  EXPECT_GE(count_valid(r, 1), static_cast<std::size_t>((r.grid.columns - 2) * (r.grid.rows - 2)));

  const double uy = mean_over_valid(r, [](const SubsetMeasurement& m) { return m.relative.uy; });
  const double ux = mean_over_valid(r, [](const SubsetMeasurement& m) { return m.relative.ux; });
  report("IC-GN du/dy relative error", std::abs(uy - gamma) / gamma, 0.02);
  EXPECT_NEAR(uy, gamma, 0.02 * gamma);
  EXPECT_NEAR(ux, 0.0, 0.02 * gamma);

  const PivStrainField f = piv_total_strain(r, 1, scale_transform(1.0));
  ASSERT_GT(f.max_shear.size(), 100u);
  double gmax = 0.0, evol = 0.0;
  for (std::size_t t = 0; t < f.max_shear.size(); ++t) {
    gmax += f.max_shear[t];
    evol += f.volumetric[t];
  }
  gmax /= static_cast<double>(f.max_shear.size());
  evol /= static_cast<double>(f.max_shear.size());
  report("CST gamma_max relative error", std::abs(gmax - gamma) / gamma, 0.02);
  EXPECT_NEAR(gmax, gamma, 0.02 * gamma);
  EXPECT_NEAR(evol, 0.0, 0.02 * gamma);
}

}  // namespace
}  // namespace trapdem

namespace trapdem {
namespace {

// With realistic noise (Gaussian, 2 grey levels = 1 % of the 200-level contrast, 8-bit): the
// figures quoted in docs/piv.md. Random error grows as sigma_noise / sqrt(SSSIG) (Pan et al. 2008).
TEST(PivAccuracy, RigidShiftAndStrainWithNoise) {
  SpeckleSettings speckle;
  speckle.noise_std = 2.0;
  const DisplacementField shift = rigid_shift(0.35, -0.65);
  const DisplacementField strain = uniform_strain(0.01, -0.01, {128.0, 128.0});
  const auto images = synthesize_speckle_sequence(speckle, {shift, strain});
  const PivResult a = run_piv(std::vector<cv::Mat>{images[0], images[1]}, PivSettings{});
  const auto [eu, ev] = test::displacement_errors(a, 1, shift);
  const auto su = statistics(eu), sv = statistics(ev);
  report("noise 2 grey levels: shift systematic error u (px)", std::abs(su.mean), 0.005);
  report("noise 2 grey levels: shift systematic error v (px)", std::abs(sv.mean), 0.005);
  report("noise 2 grey levels: shift standard deviation u (px)", su.std, 0.02);
  report("noise 2 grey levels: shift standard deviation v (px)", sv.std, 0.02);
  EXPECT_LT(std::abs(su.mean), 0.005);
  EXPECT_LT(std::abs(sv.mean), 0.005);
  EXPECT_LT(su.std, 0.02);
  EXPECT_LT(sv.std, 0.02);

  const PivResult b = run_piv(std::vector<cv::Mat>{images[0], images[2]}, PivSettings{});
  const double ux = [&] {
    double s = 0.0;
    int n = 0;
    for (const auto& m : b.image[1].subset)
      if (m.is_valid()) s += m.relative.ux, ++n;
    return s / n;
  }();
  const PivStrainField f = piv_total_strain(b, 1, scale_transform(1.0));
  double sxx = 0.0;
  for (const auto& e : f.strain) sxx += e.exx;
  sxx /= static_cast<double>(f.strain.size());
  report("noise 2 grey levels: 1 % strain, IC-GN du/dx relative error", std::abs(ux - 0.01) / 0.01, 0.02);
  report("noise 2 grey levels: 1 % strain, CST e_xx relative error", std::abs(sxx + 0.01) / 0.01, 0.02);
  EXPECT_NEAR(ux, 0.01, 0.0002);
  EXPECT_NEAR(sxx, -0.01, 0.0002);
}

}  // namespace
}  // namespace trapdem
