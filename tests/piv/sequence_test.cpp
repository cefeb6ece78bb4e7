// Large displacements over a sequence: followed by extrapolated starts, integer-pixel seeds and
// reference updating (leapfrog); total displacement from image 1 per subset and image.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"
#include "piv_test_support.hpp"

namespace trapdem {
namespace {

using test::report;
using test::statistics;

void print_sequence(const PivResult& r, const std::vector<DisplacementField>& fields,
                    const std::function<bool(cv::Point2d)>& include = {}) {
  for (std::size_t k = 1; k < r.image_count(); ++k) {
    const auto [eu, ev] = test::displacement_errors(r, k, fields[k - 1], include);
    std::printf("image %2zu (reference %zu): %3zu valid; u error mean %+.4f std %.4f; v error mean %+.4f std %.4f px\n",
                k + 1, r.image[k].reference + 1, count_valid(r, k), statistics(eu).mean, statistics(eu).std,
                statistics(ev).mean, statistics(ev).std);
  }
}

// A rigid translation of 46 px x 28 px in ten steps of 4.6 x 2.8 px, more than the subset size
// in total: every subset that stays in the image is followed to within 0.01 px.
TEST(PivSequence, LargeTranslationFollowed) {
  SpeckleSettings speckle;
  speckle.margin = 64.0;
  std::vector<DisplacementField> fields;
  for (int k = 1; k <= 10; ++k) fields.push_back(rigid_shift(4.6 * k, -2.8 * k));
  const auto images = synthesize_speckle_sequence(speckle, fields);
  const PivResult r = run_piv(images, PivSettings{});
  print_sequence(r, fields);
  // Subsets whose warped square stays inside the last image.
  std::size_t inside = 0;
  for (const auto& c : r.grid.centre)
    if (c.x + 15.5 + 46.0 <= 255.0 && c.y - 15.5 - 28.0 >= 0.0) ++inside;
  EXPECT_GE(count_valid(r, 10), inside);
  const auto [eu, ev] = test::displacement_errors(r, 10, fields.back());
  const auto su = statistics(eu), sv = statistics(ev);
  report("largest |u error| after 46 px (px)", su.max_abs, 0.01);
  report("largest |v error| after 28 px (px)", sv.max_abs, 0.01);
  EXPECT_LT(su.max_abs, 0.01);
  EXPECT_LT(sv.max_abs, 0.01);
}

// A trapdoor-like settlement growing to 40 px (more than a subset) with two shear bands 6 px
// wide: the subsets across a band decorrelate, the reference is updated, and the soil inside
// and outside the settling column is followed to the end (subsets clear of the bands).
TEST(PivSequence, TrapdoorSettlementFollowedWithReferenceUpdating) {
  SpeckleSettings speckle;
  TrapdoorSettlement t;
  t.centre_x = 128.0;
  t.width = 80.0;
  t.base_y = 256.0;
  t.settlement = 40.0;
  t.band_angle_deg = 10.0;
  t.band_width = 6.0;
  std::vector<DisplacementField> fields;
  for (int k = 1; k <= 10; ++k) fields.push_back(scaled(trapdoor_settlement(t), k / 10.0));
  const auto images = synthesize_speckle_sequence(speckle, fields);
  const PivResult r = run_piv(images, PivSettings{});

  // Clear of the bands: more than half a subset diagonal plus the band width from either band.
  const double lean = std::tan(t.band_angle_deg * std::numbers::pi / 180.0);
  auto clear_of_bands = [&](cv::Point2d c) {
    const double height = t.base_y - c.y;
    const double left = t.centre_x - 0.5 * t.width - height * lean;
    const double right = t.centre_x + 0.5 * t.width + height * lean;
    return std::min(std::abs(c.x - left), std::abs(c.x - right)) > 0.5 * std::sqrt(2.0) * 32.0 + t.band_width;
  };
  print_sequence(r, fields, clear_of_bands);
  std::printf("references:");
  for (auto k : r.reference_images) std::printf(" %zu", k + 1);
  std::printf("\n");
  EXPECT_GT(r.reference_images.size(), 1u) << "the reference was never updated";

  const auto [eu, ev] = test::displacement_errors(r, 10, fields.back(), clear_of_bands);
  const auto su = statistics(eu), sv = statistics(ev);
  ASSERT_GT(ev.size(), 60u);
  report("subsets clear of the bands followed to image 11", static_cast<double>(ev.size()), 60);
  report("v systematic error after 40 px settlement (px)", std::abs(sv.mean), 0.02);
  report("v standard deviation after 40 px settlement (px)", sv.std, 0.02);
  report("u standard deviation (px)", su.std, 0.02);
  EXPECT_LT(std::abs(sv.mean), 0.02);
  EXPECT_LT(sv.std, 0.02);
  EXPECT_LT(std::abs(su.mean), 0.02);
  EXPECT_LT(su.std, 0.02);
  // The settling column itself is followed: some subsets moved the full 40 px.
  std::size_t moved = 0;
  for (const auto& m : r.image[10].subset) moved += m.is_valid() && m.v > 39.0 ? 1 : 0;
  EXPECT_GT(moved, 5u);
}

}  // namespace
}  // namespace trapdem
