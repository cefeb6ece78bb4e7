// Smoke test on three of the real uplift photographs (shared/data/uplift-photos: a plate pulled up
// through sand behind a window), halved to 2048 x 1500 px: the sand is followed from the first to
// the last photograph of the sequence, with reference updating, and the soil above the plate
// heaves. Fails when the shared data are not there.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "../shared_data.hpp"
#include "piv/run_piv.hpp"

namespace trapdem {
namespace {

TEST(PivRealPhotographs, UpliftSequenceFollowedAndHeaveAboveThePlate) {
  const std::filesystem::path dir = test::shared_dir() / "data" / "uplift-photos";
  const std::vector<std::filesystem::path> files = {dir / "IMG_00.jpg", dir / "IMG_40.jpg", dir / "IMG_68.jpg"};
  ASSERT_TRUE(test::shared_files_present(files));

  constexpr double scale = 0.5;  // 4096 x 3000 -> 2048 x 1500
  PivSettings settings;
  settings.subset_size = 32;
  settings.step = 32;
  settings.search_radius = 24;
  settings.roi = RegionOfInterest{0, 640, 2048, 1500};  // the sand below the surface (rows 1280-3000 full size)
  const auto start = std::chrono::steady_clock::now();
  const PivResult r = run_piv(
      files.size(),
      [&](std::size_t k) {
        GreyImage g = read_grey_image(files[k]);
        cv::Mat half;
        cv::resize(g.intensity, half, cv::Size(), scale, scale, cv::INTER_AREA);
        g.intensity = half;
        return g;
      },
      [&](std::size_t k) { return files[k].string(); }, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::size_t last = r.image_count() - 1;
  std::size_t valid = 0;
  double zncc_sum = 0.0;
  for (const auto& m : r.image[last].subset)
    if (m.is_valid()) {
      ++valid;
      zncc_sum += m.zncc;
    }
  std::printf("[ measured ] %zu subsets, %zu valid in the last image, mean ZNCC %.3f, references", r.grid.size(),
              valid, zncc_sum / std::max<std::size_t>(valid, 1));
  for (auto k : r.reference_images) std::printf(" %zu", k + 1);
  std::printf("; %.1f s for 3 images\n", seconds);

  // Vertical displacement (px, up negative in the image) of the sand above the plate (full-size
  // columns 1700-2300, rows 1300-1900) and of the sand far to the sides.
  auto median_v = [&](double x0, double x1, double y0, double y1) {
    std::vector<double> v;
    for (std::size_t i = 0; i < r.grid.size(); ++i) {
      const cv::Point2d c = r.grid.centre[i] / scale;
      const auto& m = r.image[last].subset[i];
      if (m.is_valid() && c.x >= x0 && c.x < x1 && c.y >= y0 && c.y < y1) v.push_back(m.v / scale);
    }
    if (v.empty()) return std::nan("");
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double above_plate = median_v(1700, 2300, 1300, 1900);
  const double far_left = median_v(0, 600, 1300, 2900);
  const double far_right = median_v(3500, 4096, 1300, 2900);
  std::printf("[ measured ] median v (full-size px): above the plate %.1f, far left %.2f, far right %.2f\n",
              above_plate, far_left, far_right);

  EXPECT_GT(valid, r.grid.size() * 7 / 10);
  EXPECT_GT(zncc_sum / static_cast<double>(valid), 0.9);
  EXPECT_LT(above_plate, -20.0);  // heave: the sand above the plate rose
  EXPECT_LT(std::abs(far_left), 2.0);
  EXPECT_LT(std::abs(far_right), 2.0);
}

}  // namespace
}  // namespace trapdem
