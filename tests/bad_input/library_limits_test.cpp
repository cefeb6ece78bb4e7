// Issue 14: sizes and results computed from user values are checked where they are computed (the
// library, not the commands): grids and images estimate their memory before allocating and refuse
// with the figure, and the sinkhole estimate refuses a non-finite result.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "analysis/dem_piv_comparison.hpp"
#include "analysis/grid_field.hpp"
#include "analysis/sinkhole.hpp"
#include "core/errors.hpp"
#include "piv/dem_camera.hpp"
#include "piv/speckle_synthesis.hpp"

namespace trapdem {
namespace {

template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::vector<Point2> kBox = {{0.0, 0.0}, {0.08, 0.04}};  // m: a tiny run's section

TEST(LibraryLimits, GridsEstimateTheirMemoryFirst) {
  EXPECT_EQ(refusal([] { grid_covering(kBox, 0.002); }), "");
  const std::string m = refusal([] { grid_covering(kBox, 1e-9); });
  SCOPED_TRACE(m);
  EXPECT_NE(m.find("grid spacing 1e-09 m"), std::string::npos);
  EXPECT_NE(m.find("bytes per field"), std::string::npos);
  EXPECT_NE(m.find("a spacing of at least"), std::string::npos);
  const std::string c = refusal([] { common_grid(kBox, kBox, 1e-7); });
  EXPECT_NE(c.find("the comparison grid spacing 1e-07 m"), std::string::npos) << c;
  EXPECT_NE(c.find("GiB per field"), std::string::npos) << c;
  EXPECT_NE(refusal([] { check_grid_memory(0.08, 0.04, std::numeric_limits<double>::quiet_NaN(), "--grid"); })
                .find("positive finite spacing"),
            std::string::npos);
}

TEST(LibraryLimits, SpeckleImagesEstimateTheirMemoryAndRefuseNanNoise) {
  SpeckleSettings s;
  s.width = 200000;
  s.height = 200000;
  const std::string m = refusal([&] { make_speckle_pattern(s); });
  EXPECT_NE(m.find("200000 x 200000 px"), std::string::npos) << m;
  EXPECT_NE(m.find("bytes of working memory"), std::string::npos) << m;
  s.width = s.height = 64;
  s.noise_std = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal([&] { make_speckle_pattern(s); }).find("noise nan"), std::string::npos);
  s.noise_std = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal([&] { synthesize_speckle_sequence(s, {rigid_shift(1.0, 0.0)}); }).find("noise inf"),
            std::string::npos);
  s.noise_std = 1.0;
  EXPECT_NE(refusal([&] { synthesize_speckle_sequence(s, {rigid_shift(std::nan(""), 0.0)}); }).find("not finite"),
            std::string::npos);
}

// `trapdem render --px-per-mm`: the view's size in pixels is estimated from the scale before it
// becomes an int (1e9 px per mm over 80 mm overflowed int: undefined behaviour) or an image.
TEST(LibraryLimits, CameraViewEstimatesItsSizeFirst) {
  Snapshot s;
  s.id = {1, 2};
  s.position = {{0.01, 0.001, 0.005}, {0.07, 0.001, 0.03}};
  s.velocity = s.angular_velocity = {{0, 0, 0}, {0, 0, 0}};
  s.radius = {0.001, 0.001};
  CameraSettings c;
  c.front_wall_y = 0.002;
  const CameraView fine = camera_view_for({s}, 0.08, 4.0, c);
  EXPECT_EQ(fine.width, 321);  // 80 mm at 4 px/mm, both edges
  const std::string m = refusal([&] { camera_view_for({s}, 0.08, 1e9, c); });
  EXPECT_NE(m.find("--px-per-mm 1e+09: the view of 80 x 35 mm would be 8e+10 x 3.5e+10 px; expected at most "
                   "1.34e+08 px (1 GiB as doubles): a scale of at most 219 px per mm"),
            std::string::npos)
      << m;
  EXPECT_NE(refusal([&] { camera_view_for({s}, 0.08, std::numeric_limits<double>::infinity(), c); })
                .find("--px-per-mm inf: expected a finite number > 0"),
            std::string::npos);
  s.position[1].z = std::numeric_limits<double>::infinity();  // a damaged snapshot
  EXPECT_NE(refusal([&] { camera_view_for({s}, 0.08, 4.0, c); }).find("would be"), std::string::npos);
}

TEST(LibraryLimits, SinkholeRefusesANonFiniteDiameter) {
  EXPECT_EQ(refusal([] { scenario_supposition(2.0, {parse_layer("12:30")}); }), "");
  const std::string m = refusal([] { scenario_supposition(2.0, {parse_layer("1e308:89.99")}); });
  EXPECT_NE(m.find("layer 1"), std::string::npos) << m;
  EXPECT_NE(m.find("D_s = inf m"), std::string::npos) << m;
  EXPECT_NE(refusal([] { parse_layer("nan:30"); }), "");
}

}  // namespace
}  // namespace trapdem
