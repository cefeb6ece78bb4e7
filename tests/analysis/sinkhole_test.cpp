// The sinkhole-size estimates: scenario supposition D_s = D_throat + 2 sum t_i tan(alpha_i) against
// hand-worked cases, the SANS 1936 size classes at their boundaries, the DEM-run scaling from a tiny
// synthetic run folder, and bad input.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/json.hpp"
#include "analysis/sinkhole.hpp"
#include "study/sinkhole_run.hpp"
#include "core/errors.hpp"
#include "sinkhole_command.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

// tan 30 = 1/sqrt(3) = 0.5773502692, tan 45 = 1, tan 60 = sqrt(3) = 1.7320508076.
constexpr double kTan30 = 0.5773502691896258;
constexpr double kTan60 = 1.7320508075688772;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("trapdem_sinkhole_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir / "analysis");
  return dir;
}

// A run folder with only what `sinkhole --from` reads: N = 40, B = 50 mm, fill 150 mm, a surface zone
// 200 mm wide and bands at 10 and 20 degrees.
fs::path synthetic_run(const std::string& name, bool with_surface_height = true, const std::string& warning = "") {
  const fs::path dir = fresh_dir(name);
  std::ofstream(dir / "resolved.toml") << "name = \"tiny\"\n[spin_up]\ng_level = 40.0\n[trapdoor]\nwidth = 0.05\n"
                                          "[pluviation]\nfill_height = 0.15\n";
  std::ofstream(dir / "analysis" / "metrics.json")
      << "{\"trapdoor\": {\"width_m\": 0.05, \"travel_m\": 0.02},\n"
         " \"shear_bands\": {\"left\": {\"angle_deg\": 10.0}, \"right\": {\"angle_deg\": 20.0}},\n"
         " \"zone_of_influence\": {\"settlement_fraction\": 0.05, "
      << (with_surface_height ? "\"surface_height_m\": 0.16, " : "\"surface_height_m\": null, ")
      << "\"surface_width_m\": 0.2}"
      << (warning.empty() ? std::string() : ", \"warnings\": [\"" + warning + "\"]") << "}\n";
  return dir;
}

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

// Prototype = model x N with N = 40: throat 0.05 x 40 = 2 m, blanket 0.16 x 40 = 6.4 m (the measured
// surface), DEM surface zone 0.2 x 40 = 8 m (large). Angle from the surface zone
// atan((8 - 2) / (2 x 6.4)) = atan(0.46875) = 25.114 deg; from the bands (10 + 20) / 2 = 15 deg.
// Supposition at 30 deg: 2 + 2 x 6.4 x tan 30 = 2 + 7.390 = 9.390 m; ratio 9.390 / 8 = 1.1738.
TEST(Sinkhole, ScalesSyntheticRun) {
  const fs::path dir = synthetic_run("scale");
  const DemRunGeometry run = read_dem_run(dir);
  EXPECT_EQ(run.name, "tiny");
  EXPECT_DOUBLE_EQ(run.g_level, 40.0);
  EXPECT_DOUBLE_EQ(run.soil_height, 0.16);
  EXPECT_DOUBLE_EQ(run.fill_height, 0.15);
  const auto c = compare_with_dem(run, 30.0);
  EXPECT_NEAR(c.throat, 2.0, 1e-12);
  EXPECT_NEAR(c.thickness, 6.4, 1e-12);
  EXPECT_NEAR(c.dem_surface_diameter, 8.0, 1e-12);
  EXPECT_EQ(c.dem_size_class, SinkholeSizeClass::large);
  EXPECT_NEAR(c.angle_from_surface_deg, std::atan(0.46875) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(c.angle_from_bands_deg, 15.0, 1e-12);
  EXPECT_NEAR(c.supposition.surface_diameter, 2.0 + 12.8 * kTan30, 1e-9);
  EXPECT_NEAR(c.ratio, (2.0 + 12.8 * kTan30) / 8.0, 1e-9);
  // The supposition at the angle the surface zone implies gives back the DEM diameter.
  EXPECT_NEAR(compare_with_dem(run, c.angle_from_surface_deg).ratio, 1.0, 1e-9);
  fs::remove_all(dir);
}

TEST(Sinkhole, FallsBackToFillHeight) {
  const fs::path dir = synthetic_run("fill", false);
  const DemRunGeometry run = read_dem_run(dir);
  EXPECT_DOUBLE_EQ(run.soil_height, 0.15);
  EXPECT_NE(run.soil_height_source.find("fill_height"), std::string::npos);
  EXPECT_NEAR(compare_with_dem(run, 0.0).thickness, 6.0, 1e-12);
  fs::remove_all(dir);
}

TEST(Sinkhole, MissingMetricsSaysAnalyzeFirst) {
  const fs::path dir = synthetic_run("nometrics");
  fs::remove(dir / "analysis" / "metrics.json");
  try {
    read_dem_run(dir);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trapdem analyze"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(SinkholeCommand, TableAndJson) {
  app::SinkholeOptions o;
  o.throat = "1";
  o.layers = {"4:45", "6:0", "3:60"};
  const std::string table = app::sinkhole_report(o);
  EXPECT_NE(table.find("19.39 m: very large"), std::string::npos) << table;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  EXPECT_NEAR(j["surface_diameter_m"].as_number(), 19.392304845413264, 1e-9);
  EXPECT_EQ(j["size_class"].as_string(), "very large");
  EXPECT_EQ(j["layers"].size(), 3u);
}

TEST(SinkholeCommand, FromRun) {
  const fs::path dir = synthetic_run("command");
  app::SinkholeOptions o;
  o.from = dir.string();
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // no angle: required
  o.layers = {"5:30"};
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // thickness comes from the run
  o.layers = {":30"};
  o.throat = "2";
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // throat comes from the run
  o.throat.clear();
  const std::string text = app::sinkhole_report(o);
  EXPECT_NE(text.find("ratio supposition / mechanism = 1.17"), std::string::npos) << text;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  EXPECT_NEAR(j["mechanism"]["surface_diameter_m"].as_number(), 8.0, 1e-12);
  EXPECT_NEAR(j["ratio_supposition_over_mechanism"].as_number(), (2.0 + 12.8 * kTan30) / 8.0, 1e-9);
  fs::remove_all(dir);
}

// The analysis' side-wall warning travels with the run's estimate: a zone bounded by the box gives a
// DEM sinkhole size bounded by the box, and the reader must be told so beside the number.
TEST(SinkholeCommand, FromRunCarriesTheAnalysisWarnings) {
  const std::string warning = "the zone of influence reaches the left side wall";
  const fs::path dir = synthetic_run("warning", true, warning);
  app::SinkholeOptions o;
  o.from = dir.string();
  o.layers = {":30"};
  const std::string text = app::sinkhole_report(o);
  EXPECT_NE(text.find("WARNING: " + warning), std::string::npos) << text;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  ASSERT_EQ(j["model"]["warnings"].size(), 1u);
  EXPECT_EQ(j["model"]["warnings"][0].as_string(), warning);
  fs::remove_all(dir);
  const fs::path quiet = synthetic_run("nowarning");
  o.from = quiet.string();
  o.json = false;
  EXPECT_EQ(app::sinkhole_report(o).find("WARNING"), std::string::npos);
  fs::remove_all(quiet);
}
