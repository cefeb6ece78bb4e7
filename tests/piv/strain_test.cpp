// Strain from PIV displacements through the analysis module: total, incremental and accumulated
// maximum shear strain of a growing simple shear, in model units by a scale.
#include <gtest/gtest.h>

#include <numeric>

#include "piv/piv_strain.hpp"
#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"
#include "piv_test_support.hpp"

namespace trapdem {
namespace {

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

TEST(PivStrain, TotalIncrementalAndAccumulatedShear) {
  SpeckleSettings speckle;
  const cv::Point2d centre(128.0, 128.0);
  const auto images = synthesize_speckle_sequence(speckle, {simple_shear(0.01, centre), simple_shear(0.02, centre)});
  const PivResult r = run_piv(images, PivSettings{});
  const PixelToModel mm = scale_transform(0.1);  // 0.1 mm per px: strain does not depend on it

  const PivStrainField total = piv_total_strain(r, 2, mm);
  const PivStrainField step = piv_incremental_strain(r, 2, mm);
  const PivStrainField path = piv_accumulated_strain(r, 2, mm);
  ASSERT_GT(total.max_shear.size(), 100u);
  ASSERT_GT(step.max_shear.size(), 100u);
  ASSERT_GT(path.max_shear.size(), 100u);
  test::report("total gamma_max 1 -> 3 (expected 0.02)", mean(total.max_shear), 0.0004);
  test::report("incremental gamma_max 2 -> 3 (expected 0.01)", mean(step.max_shear), 0.0002);
  test::report("accumulated gamma_max 1 -> 3 (expected 0.02)", mean(path.max_shear), 0.0004);
  EXPECT_NEAR(mean(total.max_shear), 0.02, 0.0004);
  EXPECT_NEAR(mean(step.max_shear), 0.01, 0.0002);
  EXPECT_NEAR(mean(path.max_shear), 0.02, 0.0004);
  // Displacements in model units: u = 0.02 (y - 128) px, x 0.1 mm/px.
  const std::size_t k = total.subset.size() / 3;
  const cv::Point2d c = r.grid.centre[total.subset[k]];
  EXPECT_NEAR(total.displacement[k].x, 0.1 * 0.02 * (c.y - 128.0), 2e-4);
  EXPECT_NEAR(total.displacement[k].z, 0.0, 2e-4);
}

}  // namespace
}  // namespace trapdem
