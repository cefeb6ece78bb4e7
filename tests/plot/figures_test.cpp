// The figures are written as PNGs of the expected size and are not blank: each has many
// distinct colours (a colour map, text, lines), counted in the decoded image.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "../analysis/synthetic_points.hpp"
#include "png_image.hpp"
#include "analysis/analysis_run.hpp"
#include "plot/colour_map.hpp"
#include "plot/line_chart.hpp"
#include "plot/specimen_figures.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

namespace {

struct PngInfo {
  int width = 0, height = 0;
  std::size_t colours = 0;
};

PngInfo inspect(const fs::path& path) {
  const test::PngImage image = test::read_png(path);
  return {image.width, image.height, image.colours()};
}

// A small analysed specimen: a settling block between two bands leaning out at 15 degrees.
AnalysisResult synthetic_result(const std::string& name) {
  const double d = 0.002, B = 0.03, xc = 0.05, angle = 15.0 * std::numbers::pi / 180.0, sigma = 2.0 * d;
  const auto nodes = test::jittered_hex_lattice(0.001, 0.099, 0.001, 0.06, d, 0.2, 5);
  auto frame = [&](double delta) {
    AnalysisFrame f{delta == 0 ? "000000" : "000001", delta, {}};
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const Point2 p = nodes[k];
      const double nl = (p.x - xc + 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
      const double nr = -(p.x - xc - 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
      const double w = -delta * 0.25 * std::erfc(-nl / sigma / std::sqrt(2.0)) * std::erfc(-nr / sigma / std::sqrt(2.0));
      f.snapshot.id.push_back(static_cast<std::int64_t>(k));
      f.snapshot.position.push_back({p.x, 0.009, p.z + w});
      f.snapshot.radius.push_back(0.5 * d);
    }
    return f;
  };
  SpecimenGeometry g{name, 0.1, 0.01, 0.07, {xc, B, 0.0}};
  AnalysisSettings s;
  s.incremental = true;
  return analyze_frames({frame(0.0), frame(0.003), frame(0.006)}, g, s);
}

}  // namespace

TEST(Figures, SpecimenFiguresAreWrittenAndNotBlank) {
  const fs::path dir = fs::temp_directory_path() / "trapdem-figures-test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const AnalysisResult r = synthetic_result("synthetic");
  plot::write_strain_map_png(dir / "strain.png", r, plot::StrainKind::total, 0.0, 900);
  plot::write_strain_map_png(dir / "strain_inc.png", r, plot::StrainKind::incremental, 0.0, 900);
  plot::write_displacement_contours_png(dir / "contours.png", r, 900);
  plot::write_particles_png(dir / "particles.png", r, 900);
  const AnalysisResult r2 = synthetic_result("second");
  plot::write_strain_panel_png(dir / "panel.png", {&r, &r2}, 0.0, 500);
  for (const char* name : {"strain.png", "strain_inc.png", "contours.png", "particles.png"}) {
    const PngInfo info = inspect(dir / name);
    std::printf("[ measured ] %s: %d x %d, %zu colours\n", name, info.width, info.height, info.colours);
    EXPECT_EQ(info.width, 900) << name;
    EXPECT_GT(info.height, 300) << name;
    EXPECT_LT(info.height, 900) << name;
    EXPECT_GT(info.colours, 100u) << name;
  }
  const PngInfo panel = inspect(dir / "panel.png");
  EXPECT_EQ(panel.width, 2 * (500 + 10) + 150);
  EXPECT_GT(panel.colours, 100u);
}

TEST(Figures, LineChartIsWrittenAndNotBlank) {
  const fs::path path = fs::temp_directory_path() / "trapdem-line-chart.png";
  plot::LineChart chart;
  chart.title = "ground reaction";
  chart.x_label = "δ/B (-)";
  chart.y_label = "ratio (-)";
  plot::LineSeries s;
  s.name = "trapdoor";
  s.colour = {0.8, 0.1, 0.1};
  for (int k = 0; k <= 50; ++k) {
    s.x.push_back(0.01 * k);
    s.y.push_back(0.2 + 0.8 * std::exp(-20.0 * 0.01 * k));
  }
  chart.series = {s};
  chart.reference_y = {1.0};
  plot::write_line_chart_png(path, chart, 800, 500);
  const PngInfo info = inspect(path);
  EXPECT_EQ(info.width, 800);
  EXPECT_EQ(info.height, 500);
  EXPECT_GT(info.colours, 20u);
}

TEST(ColourMaps, EndsAndMiddle) {
  const plot::ColourMap viridis(plot::ColourMapKind::viridis), diverging(plot::ColourMapKind::diverging);
  EXPECT_NEAR(viridis.at(0.0).r, 0x44 / 255.0, 1e-12);
  EXPECT_NEAR(viridis.at(1.0).g, 0xe7 / 255.0, 1e-12);
  EXPECT_NEAR(viridis.at(2.0).g, 0xe7 / 255.0, 1e-12);  // clamped
  const plot::Rgb white = diverging.of(0.0, -1.0, 1.0);
  EXPECT_GT(white.r, 0.95);
  EXPECT_GT(white.b, 0.95);
  EXPECT_GT(diverging.of(-1.0, -1.0, 1.0).b, diverging.of(-1.0, -1.0, 1.0).r);  // negative blue
  // viridis lightness grows monotonically (perceptually ordered)
  double last = -1.0;
  for (int k = 0; k <= 20; ++k) {
    const plot::Rgb c = viridis.at(k / 20.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, last);
    last = luma;
  }
}
