// Bad input gives a clear InputError: images of different sizes, an unreadable file, an empty
// region of interest, a subset larger than the image (issue 5), and their relatives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/errors.hpp"
#include "piv_test_support.hpp"
#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"
#include "../scratch_dir.hpp"

namespace trapdem {
namespace {

using test::expect_input_error;

std::vector<cv::Mat> small_pair() {
  SpeckleSettings s;
  s.width = 96;
  s.height = 80;
  return synthesize_speckle_sequence(s, {rigid_shift(0.3, 0.0)});
}

TEST(PivBadInput, ImagesOfDifferentSizes) {
  auto images = small_pair();
  cv::Mat larger;
  cv::resize(images[1], larger, cv::Size(100, 80));
  images[1] = larger;
  expect_input_error([&] { run_piv(images, PivSettings{}); }, "same size");
}

TEST(PivBadInput, UnreadableFiles) {
  const test::ScratchDir dir("trapdem-piv-bad-input");
  const auto images = small_pair();
  const auto good = dir / "good.png";
  cv::imwrite(good.string(), images[0]);
  const auto text = dir / "not_an_image.png";
  std::ofstream(text) << "this is text, not a PNG\n";
  const auto missing = dir / "missing.png";
  std::filesystem::remove(missing);

  expect_input_error([&] { run_piv(std::vector<std::filesystem::path>{good, text}, PivSettings{}); },
                     "not_an_image.png");
  expect_input_error([&] { run_piv(std::vector<std::filesystem::path>{good, missing}, PivSettings{}); },
                     "no such file");
  expect_input_error([&] { read_grey_image(text); }, "cannot decode");
}

TEST(PivBadInput, EmptyRegionOfInterest) {
  PivSettings s;
  s.roi = RegionOfInterest{40, 10, 40, 70};  // zero width
  expect_input_error([&] { run_piv(small_pair(), s); }, "region of interest");
  s.roi = RegionOfInterest{50, 60, 20, 10};  // inverted
  expect_input_error([&] { run_piv(small_pair(), s); }, "empty");
}

TEST(PivBadInput, RegionOfInterestOutsideTheImageOrSmallerThanASubset) {
  PivSettings s;
  s.roi = RegionOfInterest{0, 0, 200, 80};
  expect_input_error([&] { run_piv(small_pair(), s); }, "not inside the image");
  s.roi = RegionOfInterest{0, 0, 20, 20};
  expect_input_error([&] { run_piv(small_pair(), s); }, "fits in the region of interest");
}

TEST(PivBadInput, SubsetLargerThanTheImage) {
  PivSettings s;
  s.subset_size = 128;
  expect_input_error([&] { run_piv(small_pair(), s); }, "larger than the image");
}

TEST(PivBadInput, FewerThanTwoImagesAndUnsupportedPixels) {
  expect_input_error([&] { run_piv(std::vector<cv::Mat>{small_pair()[0]}, PivSettings{}); }, "at least two");
  expect_input_error([] { to_grey_image(cv::Mat(10, 10, CV_8SC1, cv::Scalar(0))); }, "depth");
  expect_input_error([] { to_grey_image(cv::Mat()); }, "empty");
}

TEST(PivBadInput, ImageFormatsAreAccepted) {
  // 8-bit grey, 16-bit grey and 8-bit colour of the same pattern all give the same intensities.
  const cv::Mat grey8 = small_pair()[0];
  cv::Mat grey16, colour;
  grey8.convertTo(grey16, CV_16U, 257.0);
  cv::cvtColor(grey8, colour, cv::COLOR_GRAY2BGR);
  const GreyImage a = to_grey_image(grey8), b = to_grey_image(grey16), c = to_grey_image(colour);
  EXPECT_EQ(a.source_bit_depth, 8);
  EXPECT_EQ(b.source_bit_depth, 16);
  EXPECT_LT(cv::norm(a.intensity, b.intensity, cv::NORM_INF), 1e-9);
  EXPECT_LT(cv::norm(a.intensity, c.intensity, cv::NORM_INF), 1e-9);
}

}  // namespace
}  // namespace trapdem
