// A DEM run folder against a PIV output folder (src/study/run_comparison.hpp, what `trapdem compare`
// and the calibration call): the same settlement field gives zero error, a field offset by 0.2 mm
// its RMS of 2 % of the 10 mm trapdoor displacement; the images are matched by name; bad input is
// a clear error.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/errors.hpp"
#include "compare_case.hpp"
#include "study/run_comparison.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

TEST(RunComparison, SameFieldGivesZeroAndAnOffsetFieldItsKnownRms) {
  const test::CompareCase same = test::make_compare_case("trapdem-compare-same", 0.0);
  CompareOptions o = same.options();
  const CompareResult c = compare_directories(o);
  EXPECT_EQ(c.piv_image, 3u);
  EXPECT_EQ(c.piv_reference_image, 1u);
  EXPECT_NEAR(c.trapdoor_travel(), 0.01, 1e-9);
  EXPECT_GT(c.error.compared, 2000u);
  EXPECT_GT(c.error.coverage, 0.9);
  EXPECT_LT(c.error.rms_normalised(), 1e-6);

  const test::CompareCase off = test::make_compare_case("trapdem-compare-offset", 0.0002);  // PIV 0.2 mm higher everywhere
  o = off.options();
  const CompareResult d = compare_directories(o);
  EXPECT_NEAR(d.error.rms_normalised(), 0.02, 1e-6);
  EXPECT_NEAR(d.error.bias_normalised(), -0.02, 1e-6);
  EXPECT_EQ(default_compare_figure(o, d), off.run / "analysis" / "compare_10mm.png");
  write_compare_figure(d, off.run / "compare.png");
  EXPECT_TRUE(fs::exists(off.run / "compare.png"));

  // --image picks another image: 5 mm of PIV against 10 mm of DEM is far off.
  o.image = 2;
  EXPECT_GT(compare_directories(o).error.rms_normalised(), 0.2);
  o.image = 0;

  // Clear errors: unknown displacement, missing PIV, no overlap.
  o.at = "7mm";
  EXPECT_THROW(compare_directories(o), InputError);
  o.at = "10mm";
  o.piv_trapdoor = "900mm,0mm";
  EXPECT_THROW(compare_directories(o), InputError);
  o.piv_trapdoor.clear();
  o.piv_dir = (off.run / "nothing").string();
  EXPECT_THROW(compare_directories(o), InputError);
}

}  // namespace
}  // namespace trapdem
