// The sinkhole-size estimates: scenario supposition D_s = D_throat + 2 sum t_i tan(alpha_i) against
// hand-worked cases, the SANS 1936 size classes at their boundaries, the implied angle of draw, and
// bad input. A DEM run's estimate from its folder: tests/study/sinkhole_run_test.cpp.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analysis/sinkhole.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

// tan 30 = 1/sqrt(3) = 0.5773502692, tan 45 = 1, tan 60 = sqrt(3) = 1.7320508076.
constexpr double kTan30 = 0.5773502691896258;
constexpr double kTan60 = 1.7320508075688772;

}  // namespace

// One layer: throat 2.5 m under 10 m of blanket with an angle of draw of 30 degrees.
//   widening = 2 x 10 x tan 30 = 20 x 0.57735 = 11.547 m
//   D_s = 2.5 + 11.547 = 14.047 m -> large (5-15 m)
TEST(Sinkhole, OneLayerHandWorked) {
  const auto e = scenario_supposition(2.5, {{10.0, 30.0}});
  ASSERT_EQ(e.layers.size(), 1u);
  EXPECT_NEAR(e.layers[0].widening, 20.0 * kTan30, 1e-12);
  EXPECT_NEAR(e.surface_diameter, 14.047005383792516, 1e-9);
  EXPECT_NEAR(e.total_thickness, 10.0, 1e-12);
  EXPECT_EQ(e.size_class, SinkholeSizeClass::large);
}

// Three layers, cavity upward, throat 1 m:
//   layer 1: 4 m at 45 deg: 2 x 4 x 1       = 8.000 m -> diameter 9.000 m
//   layer 2: 6 m at  0 deg: 2 x 6 x 0       = 0.000 m -> diameter 9.000 m (vertical sides)
//   layer 3: 3 m at 60 deg: 2 x 3 x 1.73205 = 10.392 m -> diameter 19.392 m
//   D_s = 1 + 8 + 0 + 10.392 = 19.392 m over 13 m of blanket -> very large (> 15 m)
TEST(Sinkhole, ThreeLayersHandWorked) {
  const auto e = scenario_supposition(1.0, {{4.0, 45.0}, {6.0, 0.0}, {3.0, 60.0}});
  ASSERT_EQ(e.layers.size(), 3u);
  EXPECT_NEAR(e.layers[0].widening, 8.0, 1e-12);
  EXPECT_NEAR(e.layers[0].diameter_above, 9.0, 1e-12);
  EXPECT_NEAR(e.layers[1].widening, 0.0, 1e-12);
  EXPECT_NEAR(e.layers[1].diameter_above, 9.0, 1e-12);
  EXPECT_NEAR(e.layers[2].widening, 6.0 * kTan60, 1e-12);
  EXPECT_NEAR(e.surface_diameter, 19.392304845413264, 1e-9);
  EXPECT_NEAR(e.total_thickness, 13.0, 1e-12);
  EXPECT_EQ(e.size_class, SinkholeSizeClass::very_large);
}

// The order of the layers does not change D_s (the sum commutes); a zero angle keeps the throat.
TEST(Sinkhole, OrderAndVerticalSides) {
  const auto a = scenario_supposition(1.0, {{4.0, 45.0}, {6.0, 0.0}, {3.0, 60.0}});
  const auto b = scenario_supposition(1.0, {{3.0, 60.0}, {4.0, 45.0}, {6.0, 0.0}});
  EXPECT_NEAR(a.surface_diameter, b.surface_diameter, 1e-12);
  EXPECT_DOUBLE_EQ(scenario_supposition(3.0, {{20.0, 0.0}}).surface_diameter, 3.0);
}

TEST(Sinkhole, SizeClassBoundaries) {
  EXPECT_EQ(classify_sinkhole(0.0), SinkholeSizeClass::small);
  EXPECT_EQ(classify_sinkhole(1.999), SinkholeSizeClass::small);
  EXPECT_EQ(classify_sinkhole(2.0), SinkholeSizeClass::medium);   // "< 2 m" is strict
  EXPECT_EQ(classify_sinkhole(4.999), SinkholeSizeClass::medium);
  EXPECT_EQ(classify_sinkhole(5.0), SinkholeSizeClass::large);    // shared boundary: the larger class
  EXPECT_EQ(classify_sinkhole(15.0), SinkholeSizeClass::large);   // "> 15 m" is strict
  EXPECT_EQ(classify_sinkhole(15.001), SinkholeSizeClass::very_large);
  EXPECT_STREQ(size_class_name(SinkholeSizeClass::very_large), "very large");
  EXPECT_STREQ(size_class_range(SinkholeSizeClass::medium), "2-5 m");
}

TEST(Sinkhole, ImpliedAngleOfDraw) {
  EXPECT_NEAR(implied_angle_of_draw_deg(1.0 + 2.0 * 5.0, 1.0, 5.0), 45.0, 1e-12);   // D = B + 2H
  EXPECT_NEAR(implied_angle_of_draw_deg(3.0, 3.0, 7.0), 0.0, 1e-12);                // D = B
  EXPECT_LT(implied_angle_of_draw_deg(2.0, 3.0, 7.0), 0.0);                         // narrower than B
  EXPECT_TRUE(std::isnan(implied_angle_of_draw_deg(2.0, 1.0, 0.0)));
}

TEST(Sinkhole, ParseLayer) {
  const auto l = parse_layer("12:30");
  EXPECT_DOUBLE_EQ(l.thickness, 12.0);
  EXPECT_DOUBLE_EQ(l.angle_of_draw_deg, 30.0);
  EXPECT_NEAR(parse_layer("1500mm:20.5").thickness, 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(parse_layer(" 3 m : 0 deg").angle_of_draw_deg, 0.0);
  EXPECT_TRUE(std::isnan(parse_layer(":25", "--layer", true).thickness));
  EXPECT_DOUBLE_EQ(parse_layer("25", "--layer", true).angle_of_draw_deg, 25.0);
}

TEST(Sinkhole, BadInput) {
  for (const char* text : {"-1:30", "10:90", "10:95", "10:-5", "10", "10:", "abc:30", "10:abc", "10:30:5", ":30", ""}) {
    EXPECT_THROW(parse_layer(text), InputError) << text;
  }
  EXPECT_THROW(parse_layer("95", "--layer", true), InputError);  // angle only: still in [0, 90)
  EXPECT_THROW(parse_layer(":x", "--layer", true), InputError);
}

TEST(Sinkhole, BadInputFormula) {
  EXPECT_THROW(scenario_supposition(0.0, {{1.0, 10.0}}), InputError);
  EXPECT_THROW(scenario_supposition(-2.0, {{1.0, 10.0}}), InputError);
  EXPECT_THROW(scenario_supposition(2.0, {}), InputError);
  EXPECT_THROW(scenario_supposition(2.0, {{-1.0, 10.0}}), InputError);
  EXPECT_THROW(scenario_supposition(2.0, {{1.0, 90.0}}), InputError);
  EXPECT_THROW(scenario_supposition(2.0, {{1.0, -0.1}}), InputError);
  try {
    parse_layer("5:90");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[0, 90)"), std::string::npos) << e.what();
  }
}

