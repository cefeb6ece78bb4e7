// The PIV workflows as library calls (src/piv/piv_folder.hpp, src/piv/synthetic_sequence.hpp; issue
// 37: what `trapdem piv` and `trapdem synth` do, callable from any front end): a synthetic rigid
// shift written with its truth and measured back into a folder.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../io/io_test_support.hpp"
#include "core/errors.hpp"
#include "piv/piv_folder.hpp"
#include "piv/synthetic_sequence.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

// A rigid shift of (2.5, 1.5) px at the last of three images (noise 2 grey levels): every valid
// subset measures it within 0.05 px, eight times the standard deviation docs/piv.md measures for
// that noise with 32 px subsets (0.0059 px), so a wrong image order, scale or warp fails it and
// noise does not; the folder holds what `trapdem piv --no-figures` writes.
TEST(PivFolder, SyntheticRigidShiftMeasuredBack) {
  const io_testing::ScratchDir scratch("trapdem-piv-folder");
  SyntheticSequenceOptions s;
  s.field = SyntheticField::rigid;
  s.out = scratch / "images";
  s.width = s.height = 160;
  s.images = 3;
  const SyntheticSequence written = write_synthetic_sequence(s);
  EXPECT_EQ(written.images, 3);
  EXPECT_DOUBLE_EQ(written.magnitude, 2.5);
  EXPECT_TRUE(fs::exists(scratch / "images" / "truth.csv"));

  PivFolderOptions o;
  for (int k = 1; k <= 3; ++k) o.images.push_back(scratch / "images" / ("image_00" + std::to_string(k) + ".png"));
  o.out = scratch / "piv";
  o.figures = false;
  o.settings.threads = 1;
  const PivFolderResult r = run_piv_into_folder(o);
  ASSERT_EQ(r.result.image_count(), 3u);
  EXPECT_EQ(r.unit, "px");
  EXPECT_GT(r.subsets, 0u);
  std::size_t valid = 0;
  for (const SubsetMeasurement& m : r.result.image[2].subset) {
    if (!m.is_valid()) continue;
    ++valid;
    EXPECT_NEAR(m.u, 2.5, 0.05);
    EXPECT_NEAR(m.v, 1.5, 0.05);
  }
  EXPECT_GT(valid, r.subsets / 2);
  EXPECT_TRUE(fs::exists(scratch / "piv" / "displacements.csv"));
  EXPECT_TRUE(fs::exists(scratch / "piv" / "piv.h5"));
  EXPECT_EQ(r.written.size(), 2u);
}

TEST(PivFolder, OptionsThatDoNotFitAreRefused) {
  PivFolderOptions o;
  o.images = {"a.png"};
  o.out = "out";
  EXPECT_THROW(run_piv_into_folder(o), InputError);  // one image
  o.images = {"a.png", "b.png"};
  o.scale_mm_per_px = 0.1;
  o.control_points = "points.csv";
  EXPECT_THROW(run_piv_into_folder(o), InputError);
  SyntheticSequenceOptions s;
  s.out = "x";
  s.width = 8;
  EXPECT_THROW(write_synthetic_sequence(s), InputError);
  EXPECT_THROW(parse_synthetic_field("wobble", "--field"), InputError);
}
