// `trapdem analyze` end to end on synthetic run folders: snapshots.h5 written with
// append_snapshot, analysed and written through analyze_and_write (src/study/run_analysis.hpp, what
// the command calls), metrics.json read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "study/run_analysis.hpp"
#include "synthetic_run.hpp"
#include "../io/io_test_support.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

namespace {

Json read_metrics(const fs::path& dir) {
  std::ifstream in(dir / "analysis" / "metrics.json");
  std::stringstream text;
  text << in.rdbuf();
  return Json::parse(text.str(), "metrics.json");
}

// In a folder of this process's own, removed at its exit (a failed test's too).
fs::path scratch(const std::string& name) {
  static const io_testing::ScratchDir root("trapdem-analyze");
  return root / name;
}

double standard_normal_cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }

}  // namespace

// A uniform vertical compression w = -eps z (scaled with the trapdoor travel): every triangle has
// e_zz = eps, e_xx = gamma_xz = 0, so gamma_max = e_vol = eps. Tolerance 1e-9 (round-off on
// coordinates of 0.1 m). The incremental strain over 0 -> 0.5 -> 1 mm sums the two increments,
// each over the geometry at its start: eps/2 + (eps/2)/(1 - eps/2), within 1e-9.
TEST(AnalyzePipeline, UniformVerticalStrainGivesThatStrainEverywhere) {
  const double eps = 0.01;
  const auto run = test::make_synthetic_run(scratch("uniform"), {0.0, 0.0005, 0.001},
                                            [&](Point2 p, double delta) { return Point2{0.0, -eps * p.z * delta / 0.001}; });
  AnalyzeOptions o;
  o.dir = run.dir.string();
  o.at = "1mm";
  o.incremental = true;
  o.no_figures = true;
  o.quiet = true;
  analyze_and_write(o);
  const Json m = read_metrics(run.dir);
  EXPECT_NEAR(m["strain"]["gamma_max_median"].as_number(), eps, 1e-9);
  EXPECT_NEAR(m["strain"]["gamma_max_max"].as_number(), eps, 1e-9);
  EXPECT_NEAR(m["strain"]["volumetric_median"].as_number(), eps, 1e-9);
  EXPECT_NEAR(m["strain"]["gamma_max_incremental_max"].as_number(), 0.5 * eps + 0.5 * eps / (1.0 - 0.5 * eps), 1e-9);
  EXPECT_EQ(m["inputs"]["view"].as_string(), "front");
  EXPECT_NEAR(m["inputs"]["at_m"].as_number(), 0.001, 1e-15);
  EXPECT_NEAR(m["inputs"]["reference_m"].as_number(), 0.0, 1e-15);
  EXPECT_NEAR(m["inputs"]["front_depth_m"].as_number(), 0.003, 1e-12);  // 1.5 x 2 mm
  EXPECT_EQ(m["inputs"]["increments"].as_number(), 2);
  EXPECT_EQ(m["particles"]["viewed"].as_number(), static_cast<double>(run.front_count));
  EXPECT_NEAR(m["particles"]["mean_diameter_m"].as_number(), 0.002, 1e-15);
  const Json& t = m["triangles"];
  EXPECT_EQ(t["kept"].as_number() + t["dropped_long_edge"].as_number() + t["dropped_sliver"].as_number(),
            t["delaunay"].as_number());
  EXPECT_GT(t["kept"].as_number(), 1.5 * run.front_count);
  EXPECT_TRUE(fs::exists(run.dir / "analysis" / "fields.h5"));
  EXPECT_TRUE(fs::exists(run.dir / "analysis" / "fields.xmf"));

  // --view all takes the particles behind the front slab too.
  o.view = "all";
  o.incremental = false;
  analyze_and_write(o);
  EXPECT_EQ(read_metrics(run.dir)["particles"]["viewed"].as_number(),
            static_cast<double>(run.front_count + run.back_count));
}

// Two planar bands leaning outward at 20 degrees from the trapdoor edges, 5 d wide (the block
// between them moves down with the trapdoor): the metrics report the angle within 2 degrees and
// the width within one diameter (the tolerances), through the whole analysis of a run folder.
TEST(AnalyzePipeline, TwoPlanarBandsGiveTheirAngleAndWidth) {
  const double d = 0.002, B = 0.05, xc = 0.1, angle = 20.0 * std::numbers::pi / 180.0;
  const double sigma = 5.0 * d / 2.3548200450309493;
  auto field = [&](Point2 p, double delta) {
    const double n_left = (p.x - xc + 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
    const double n_right = -(p.x - xc - 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
    return Point2{0.0, -delta * standard_normal_cdf(n_left / sigma) * standard_normal_cdf(n_right / sigma)};
  };
  const auto run = test::make_synthetic_run(scratch("bands"), {0.0, 0.005, 0.01}, field);
  AnalyzeOptions o;
  o.dir = run.dir.string();
  o.at = "10 mm";
  o.reference = "0";
  o.no_figures = true;
  o.quiet = true;
  analyze_and_write(o);
  const Json m = read_metrics(run.dir);
  for (const char* side : {"left", "right"}) {
    const Json& band = m["shear_bands"][side];
    std::printf("[ measured ] %s band: angle %.2f deg (20 +/- 2), width %.2f d (5 +/- 1), height %.1f mm\n", side,
                band["angle_deg"].as_number(), band["width_diameters"].as_number(),
                band["height_reached_m"].as_number() * 1e3);
    EXPECT_NEAR(band["angle_deg"].as_number(), 20.0, 2.0) << side;
    EXPECT_NEAR(band["width_diameters"].as_number(), 5.0, 1.0) << side;
    EXPECT_GT(band["height_reached_m"].as_number(), 0.1) << side;
  }
  // The settled block widens upward: wider than B at the surface, elliptical-ish shape ratio > 1.
  EXPECT_GT(m["zone_of_influence"]["surface_width_m"].as_number(), B);
  EXPECT_GT(m["zone_of_influence"]["shape_ratio"].as_number(), 1.0);
  // Bands at 20 deg make no column: the zone's width decides the shape, by its own rule.
  EXPECT_EQ(m["zone_of_influence"]["shape_from"].as_string(), "zone_width");
  EXPECT_EQ(m["zone_of_influence"]["shape"].as_string(),
            m["zone_of_influence"]["shape_ratio"].as_number() < 1.3 ? "columnar" : "elliptical");
  EXPECT_NEAR(m["trapdoor"]["travel_over_B"].as_number(), 0.2, 1e-12);
}

TEST(AnalyzePipeline, MissingDisplacementNamesTheAvailableOnes) {
  const auto run = test::make_synthetic_run(scratch("missing"), {0.0, 0.001},
                                            [](Point2, double delta) { return Point2{0.0, -delta}; }, 0.02);
  AnalyzeOptions o;
  o.dir = run.dir.string();
  o.at = "80mm";
  o.quiet = true;
  try {
    analyze_and_write(o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--at 80 mm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0 mm, 1 mm"), std::string::npos) << e.what();
  }
  o.at = "1mm";
  o.view = "side";
  EXPECT_THROW(analyze_and_write(o), InputError);
  o.view = "front";
  o.grid = "-2mm";
  EXPECT_THROW(analyze_and_write(o), InputError);
}
