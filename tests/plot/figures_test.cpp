// The figures are written as PNGs of the expected size and are not blank: each has many
// distinct colours (a colour map, text, lines), counted in the decoded image. SVG and PDF start with
// their magic and hold the figure's title as text; the volumetric strain map is red where the soil
// compresses and blue where it dilates; contour levels follow the option; panels share one scale.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "../analysis/synthetic_points.hpp"
#include "../io/io_test_support.hpp"
#include "png_image.hpp"
#include "analysis/analysis_run.hpp"
#include "core/errors.hpp"
#include "io/text_file.hpp"
#include "plot/canvas.hpp"
#include "plot/colour_map.hpp"
#include "plot/contour_plot.hpp"
#include "plot/figure_format.hpp"
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

// Frames of a jittered lattice of 2 mm particles over a 0.1 x 0.06 m specimen, each node moved by
// w(p, delta) vertically.
AnalysisFrame lattice_frame(double delta, const std::function<double(Point2, double)>& w) {
  static const auto nodes = test::jittered_hex_lattice(0.001, 0.099, 0.001, 0.06, 0.002, 0.2, 5);
  AnalysisFrame f{delta == 0 ? "000000" : "000001", delta, {}};
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Point2 p = nodes[k];
    f.snapshot.id.push_back(static_cast<std::int64_t>(k));
    f.snapshot.position.push_back({p.x, 0.009, p.z + w(p, delta)});
    f.snapshot.radius.push_back(0.001);
  }
  return f;
}

// A small analysed specimen: a settling block between two bands leaning out at 15 degrees.
AnalysisResult synthetic_result(const std::string& name) {
  const double d = 0.002, B = 0.03, xc = 0.05, angle = 15.0 * std::numbers::pi / 180.0, sigma = 2.0 * d;
  const auto w = [&](Point2 p, double delta) {
    const double nl = (p.x - xc + 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
    const double nr = -(p.x - xc - 0.5 * B) * std::cos(angle) + p.z * std::sin(angle);
    return -delta * 0.25 * std::erfc(-nl / sigma / std::sqrt(2.0)) * std::erfc(-nr / sigma / std::sqrt(2.0));
  };
  SpecimenGeometry g{name, 0.1, 0.01, 0.07, {xc, B, 0.0}};
  AnalysisSettings s;
  s.incremental = true;
  return analyze_frames({lattice_frame(0.0, w), lattice_frame(0.003, w), lattice_frame(0.006, w)}, g, s);
}

// Each test writes into a folder of its own (mkdtemp), removed at its end: two runs of the tests at
// once (two work trees, or ctest -j) never write to the same files.
using ScratchDir = io_testing::ScratchDir;

}  // namespace

TEST(Figures, SpecimenFiguresAreWrittenAndNotBlank) {
  const ScratchDir scratch;
  const fs::path& dir = scratch.path();
  const AnalysisResult r = synthetic_result("synthetic");
  plot::write_strain_map(dir / "strain.png", r, plot::StrainKind::total, 0.0, 450);
  plot::write_strain_map(dir / "strain_inc.png", r, plot::StrainKind::incremental, 0.0, 450);
  plot::write_volumetric_strain_map(dir / "volumetric.png", r, 0.0, 450);
  plot::write_displacement_contours(dir / "contours.png", r, {}, 450);
  plot::write_particles_figure(dir / "particles.png", r, 450);
  const AnalysisResult r2 = synthetic_result("second");
  plot::write_strain_panel(dir / "panel.png", {&r, &r2});
  for (const char* name : {"strain.png", "strain_inc.png", "volumetric.png", "contours.png", "particles.png"}) {
    const PngInfo info = inspect(dir / name);
    std::printf("[ measured ] %s: %d x %d, %zu colours\n", name, info.width, info.height, info.colours);
    EXPECT_EQ(info.width, 450 * plot::kPngPixelsPerUnit) << name;
    EXPECT_GT(info.height, 150 * plot::kPngPixelsPerUnit) << name;
    EXPECT_LT(info.height, 900 * plot::kPngPixelsPerUnit) << name;
    EXPECT_GT(info.colours, 100u) << name;
  }
  const PngInfo panel = inspect(dir / "panel.png");
  EXPECT_EQ(panel.width, static_cast<int>(plot::kFigureWidth * plot::kPngPixelsPerUnit));
  EXPECT_GT(panel.colours, 100u);
}

TEST(Figures, LineChartIsWrittenAndNotBlank) {
  const ScratchDir scratch;
  const fs::path path = scratch / "line-chart.png";
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
  plot::write_line_chart(path, chart, 400, 250);
  const PngInfo info = inspect(path);
  EXPECT_EQ(info.width, 400 * plot::kPngPixelsPerUnit);
  EXPECT_EQ(info.height, 250 * plot::kPngPixelsPerUnit);
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

namespace {

// The file's bytes.
std::string bytes_of(const fs::path& path) { return read_text_file(path); }

// How cairo's PDF writer spells a title: UTF-16BE hex after a byte order mark (ASCII text here).
std::string pdf_utf16_hex(const std::string& ascii) {
  std::string hex = "FEFF";
  for (unsigned char c : ascii) hex += fmt::format("00{:02X}", c);
  return hex;
}

}  // namespace

TEST(FigureFormats, TheExtensionPicksPngSvgOrPdf) {
  const ScratchDir scratch;
  const fs::path& dir = scratch.path();
  const AnalysisResult r = synthetic_result("synthetic");
  for (const char* ext : {".png", ".svg", ".pdf", ".PDF"}) plot::write_strain_map(dir / ("strain" + std::string(ext)), r, plot::StrainKind::total);
  const std::string png = bytes_of(dir / "strain.png"), svg = bytes_of(dir / "strain.svg"), pdf = bytes_of(dir / "strain.pdf");
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(svg.substr(0, 5), "<?xml");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("<title>synthetic: maximum shear strain γmax (total)</title>"), std::string::npos);
  EXPECT_NE(svg.find("<path"), std::string::npos);  // vector triangles, not one image
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/Title <" + pdf_utf16_hex("synthetic: maximum shear strain ")), std::string::npos);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
  EXPECT_EQ(bytes_of(dir / "strain.PDF").substr(0, 5), "%PDF-");
  // Vector files are sized in points: one layout unit each.
  EXPECT_NE(svg.find("width=\"640pt\""), std::string::npos);
  EXPECT_THROW(plot::write_strain_map(dir / "strain.jpg", r, plot::StrainKind::total), InputError);
  EXPECT_FALSE(fs::exists(dir / "strain.jpg"));
  EXPECT_EQ(plot::parse_figure_format("SVG"), plot::FigureFormat::svg);
  EXPECT_THROW(plot::parse_figure_format("eps"), InputError);
  EXPECT_EQ(plot::with_format(dir / "a.png", plot::FigureFormat::pdf).filename(), "a.pdf");
}

// A specimen compressed vertically on the left of x = 50 mm (w = -e z: the area shrinks, εv > 0)
// and stretched on the right (w = +e z: εv < 0, dilation).
TEST(VolumetricStrainMap, CompressionRedDilationBlue) {
  const double e = 0.02;
  const auto w = [&](Point2 p, double delta) { return (p.x < 0.05 ? -1.0 : 1.0) * e * p.z * delta / 0.003; };
  const AnalysisResult r = analyze_frames({lattice_frame(0.0, w), lattice_frame(0.003, w)},
                                          {"signs", 0.1, 0.01, 0.07, {0.05, 0.03, 0.0}}, {});
  const ScratchDir scratch;
  const fs::path png = scratch / "volumetric.png";
  const plot::PlotFrame f = plot::write_volumetric_strain_map(png, r);
  const test::PngImage image = test::read_png(png);
  auto pixel = [&](double x_mm, double z_mm) {
    return std::array<int, 2>{static_cast<int>(f.px(x_mm) * plot::kPngPixelsPerUnit),
                              static_cast<int>(f.py(z_mm) * plot::kPngPixelsPerUnit)};
  };
  const auto left = pixel(20.0, 30.0), right = pixel(80.0, 30.0);
  EXPECT_GT(image.red(left[0], left[1]), image.blue(left[0], left[1]) + 60) << "compression is red";
  EXPECT_GT(image.blue(right[0], right[1]), image.red(right[0], right[1]) + 60) << "dilation is blue";
  const std::vector<double> shown = plot::shown_volumetric_strain(r);
  ASSERT_EQ(shown.size(), r.mesh.mesh.size());
}

TEST(ContourLevels, ListStepOrAutomatic) {
  EXPECT_EQ(plot::contour_levels({{2.0, 0.5, 1.0, 1.0}, 0.0}, 0.0, 3.0), (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(plot::contour_levels({{}, 0.5}, -0.2, 2.1), (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
  EXPECT_EQ(plot::contour_levels({{}, 1.0}, -2.5, 1.0), (std::vector<double>{-2.0, -1.0}));  // heave too, not 0
  EXPECT_EQ(plot::contour_levels({}, 0.0, 3.0), (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
  EXPECT_THROW(plot::contour_levels({{}, 1e-9}, 0.0, 1.0), InputError);
  EXPECT_EQ(plot::contour_label(0.30000000004, {0.1, 0.2, 0.3}), "0.3");
  EXPECT_EQ(plot::contour_label(2.0, {1.0, 2.0}), "2");
  EXPECT_EQ(plot::contour_label(-1.5, {-1.5, 1.5}), "-1.5");
}

// Two runs of different box widths and depths of fill: one length scale (units per mm), one
// vertical range, their bases on one line.
TEST(StrainPanel, PanelsShareOneLengthScale) {
  const AnalysisResult a = synthetic_result("a");
  AnalysisResult b = synthetic_result("b");
  b.geometry.box_width = 0.14;
  const ScratchDir scratch;
  const auto frames = plot::write_strain_panel(scratch / "panel-scale.svg", {&a, &b},
                                               {"case A", "case B"});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NEAR(frames[0].scale_x(), frames[1].scale_x(), 1e-12);
  EXPECT_NEAR(frames[0].pixels().h, frames[1].pixels().h, 1e-12);
  EXPECT_NEAR(frames[0].y_range().lo, frames[1].y_range().lo, 1e-12);
  EXPECT_NEAR(frames[0].pixels().w * 0.14, frames[1].pixels().w * 0.1, 1e-9);
  const std::string svg = read_text_file(scratch / "panel-scale.svg");
  EXPECT_NE(svg.find("one colour and length scale"), std::string::npos);
}

// A run whose snapshots are gone is drawn from its stored grid (field_history.h5's last layer) on
// the panel's scales: its cells in the colour of their value on the panel's one colour scale, its
// box on the same mm per unit, empty space light grey as around the triangles. A map that is both
// or neither an analysis and a stored grid is a programming error.
TEST(StrainPanel, AStoredGridIsDrawnOnThePanelsScales) {
  const AnalysisResult a = synthetic_result("a");
  plot::StoredStrainMap m;
  m.name = "stored";
  m.box_width = 0.1;
  m.trapdoor = {0.05, 0.03, 0.0};
  m.travel = 0.006;
  m.mean_diameter = 0.002;
  m.smoothing_diameters = 2.0;
  // Nodes every 2 mm over 0.1 x 0.06 m: gamma_max 1 in a stripe 10 mm wide over x = 20-30 mm, 0.1
  // elsewhere, nothing above z = 50 mm (above the surface).
  m.gamma_max.grid = GridSpec{0.001, 0.001, 0.002, 50, 30};
  for (std::size_t j = 0; j < 30; ++j)
    for (std::size_t i = 0; i < 50; ++i) {
      const double x = m.gamma_max.grid.x(i), z = m.gamma_max.grid.z(j);
      m.gamma_max.value.push_back(z > 0.05 ? std::nan("") : (x > 0.02 && x < 0.03 ? 1.0 : 0.1));
    }
  m.band_traces = {{{0.0, 0.035, 0.0, 0.0}, {0.04, 0.035, 0.0, 0.0}}};
  EXPECT_EQ(plot::auto_strain_scale(m), 1.0);  // the 95th percentile (1) rounded up: 1
  const ScratchDir scratch;
  const double vmax = 2.0;
  using Maps = std::vector<plot::StrainPanelMap>;
  const auto frames = plot::write_strain_panel_of_maps(scratch / "panel.png", Maps{{&a, nullptr}, {nullptr, &m}},
                                                       {"analysed", "stored"}, vmax);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NEAR(frames[0].scale_x(), frames[1].scale_x(), 1e-12);
  EXPECT_NEAR(frames[1].x_range().hi, 100.0, 1e-12);  // mm: the box
  const test::PngImage image = test::read_png(scratch / "panel.png");
  const auto pixel_at = [&](double x_mm, double z_mm) {
    const double k = plot::kPngPixelsPerUnit;
    return image.at(static_cast<int>(frames[1].px(x_mm) * k), static_cast<int>(frames[1].py(z_mm) * k));
  };
  const auto expected = [&](double value) {
    const plot::Rgb c = plot::ColourMap(plot::ColourMapKind::viridis).of(value, 0.0, vmax);
    const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(v * 255.0)); };
    return byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
  };
  const auto near = [](std::uint32_t a, std::uint32_t b) {  // within 2 of 255 per channel (rounding)
    for (int shift : {0, 8, 16})
      if (std::abs(static_cast<int>(a >> shift & 0xff) - static_cast<int>(b >> shift & 0xff)) > 2) return false;
    return true;
  };
  EXPECT_TRUE(near(pixel_at(25.0, 20.0), expected(1.0))) << std::hex << pixel_at(25.0, 20.0);
  EXPECT_TRUE(near(pixel_at(70.0, 20.0), expected(0.1))) << std::hex << pixel_at(70.0, 20.0);
  EXPECT_TRUE(near(pixel_at(70.0, 55.0), 0xededed)) << std::hex << pixel_at(70.0, 55.0);  // empty: light grey
  EXPECT_THROW(plot::write_strain_panel_of_maps(scratch / "bad.png", Maps{{&a, &m}}), std::invalid_argument);
  EXPECT_THROW(plot::write_strain_panel_of_maps(scratch / "bad.png", Maps{{nullptr, nullptr}}), std::invalid_argument);
}
