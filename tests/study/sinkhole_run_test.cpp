// The sinkhole estimate of a DEM run from its folder (src/study/sinkhole_run.hpp): the specimen from
// resolved.toml and the zone of influence from analysis/metrics.json, scaled to prototype by the g
// level and set beside the scenario supposition (src/analysis/sinkhole.hpp).
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "analysis/sinkhole.hpp"
#include "core/errors.hpp"
#include "sinkhole_run_folder.hpp"
#include "study/sinkhole_run.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

// Prototype = model x N with N = 40: throat 0.05 x 40 = 2 m, blanket 0.16 x 40 = 6.4 m (the measured
// surface), DEM surface zone 0.2 x 40 = 8 m (large). Angle from the surface zone
// atan((8 - 2) / (2 x 6.4)) = atan(0.46875) = 25.114 deg; from the bands (10 + 20) / 2 = 15 deg.
// Supposition at 30 deg: 2 + 2 x 6.4 x tan 30 = 2 + 7.390 = 9.390 m; ratio 9.390 / 8 = 1.1738.
TEST(SinkholeRun, ScalesSyntheticRun) {
  const test::ScratchDir dir = test::sinkhole_run_folder("scale");
  const DemRunGeometry run = read_dem_run(dir.path());
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
  EXPECT_NEAR(c.supposition.surface_diameter, 2.0 + 12.8 * test::kTan30, 1e-9);
  EXPECT_NEAR(c.ratio, (2.0 + 12.8 * test::kTan30) / 8.0, 1e-9);
  // The supposition at the angle the surface zone implies gives back the DEM diameter.
  EXPECT_NEAR(compare_with_dem(run, c.angle_from_surface_deg).ratio, 1.0, 1e-9);
}

TEST(SinkholeRun, FallsBackToFillHeight) {
  const test::ScratchDir dir = test::sinkhole_run_folder("fill", false);
  const DemRunGeometry run = read_dem_run(dir.path());
  EXPECT_DOUBLE_EQ(run.soil_height, 0.15);
  EXPECT_NE(run.soil_height_source.find("fill_height"), std::string::npos);
  EXPECT_NEAR(compare_with_dem(run, 0.0).thickness, 6.0, 1e-12);
}

TEST(SinkholeRun, MissingMetricsSaysAnalyzeFirst) {
  const test::ScratchDir dir = test::sinkhole_run_folder("nometrics");
  fs::remove(dir / "analysis" / "metrics.json");
  try {
    read_dem_run(dir.path());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trapdem analyze"), std::string::npos) << e.what();
  }
}

