// The PIV figures from plain data (src/plot/piv_figures.hpp, photo_figure.hpp): the photograph lands
// where the pixel -> plot transform puts it, and each figure draws its marks where the data says,
// read back from the PNGs. The data: a 96 x 64 px photograph at 0.5 mm/px (y flipped, so z is up),
// a 10 x 6 grid of subsets every 8 px, all moved by (1, 0.5) px, three of them flagged or without texture.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../io/io_test_support.hpp"
#include "plot/photo_figure.hpp"
#include "plot/piv_figures.hpp"
#include "png_image.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;
using plot::SubsetMark;

const plot::PixelToPlot half_mm_per_px{0.5, 0.0, 0.0, 0.0, -0.5, 0.0, 0.0, 0.0, 1.0};
constexpr int columns = 10, rows = 6, step = 8;

// A folder for one test under a folder of this program's own (mkdtemp: two runs at once, from two
// work trees or ctest -j, never share files), removed when the program ends.
fs::path scratch(const std::string& name) {
  static const io_testing::ScratchDir root;
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

plot::Photograph uniform_photograph(std::uint8_t grey) { return {96, 64, std::vector<std::uint8_t>(96 * 64, grey)}; }

Point2 centre_mm(int column, int row) { return {0.5 * (step + step * column), -0.5 * (step + step * row)}; }

// Two counter-clockwise triangles (z up) per grid cell over the subset centres, node = row * columns + column.
plot::StrainTriangles grid_triangles(double max_shear, Point2 displacement) {
  plot::StrainTriangles s;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      s.position.push_back(centre_mm(c, r));
      s.displacement.push_back(displacement);
    }
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const std::size_t a = r * columns + c, b = a + 1, below = a + columns, below_right = below + 1;
      s.mesh.triangles.push_back({below, below_right, b});
      s.mesh.triangles.push_back({below, b, a});
      s.max_shear.push_back(max_shear);
      s.max_shear.push_back(max_shear);
    }
  return s;
}

plot::PivFigureData figure_data() {
  plot::PivFigureData d;
  d.title = "test";
  d.unit = "mm";
  d.first_image = uniform_photograph(128);
  d.last_image = uniform_photograph(128);
  d.pixel_to_plot = half_mm_per_px;
  d.image_number = 3;
  d.grid_step = step;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      plot::SubsetView v{double(step + step * c), double(step + step * r), c, r, 1.0, 0.5, 0.95, SubsetMark::valid};
      d.subsets.push_back(v);
    }
  d.subsets[0].mark = SubsetMark::poor_texture;
  d.subsets[1].mark = SubsetMark::poor_texture_lost;
  d.subsets[2].mark = SubsetMark::flagged;
  d.subsets[2].zncc = 0.5;
  // Uniform strain 0.01 (the colour scale's top: viridis' yellow end); incremental half of it.
  d.total_strain = grid_triangles(0.01, {0.5, -0.25});
  d.incremental_strain = grid_triangles(0.005, {0.25, -0.125});
  // Vertical displacement from 0 on the left to -0.25 mm on the right.
  for (std::size_t i = 0; i < d.total_strain.position.size(); ++i) {
    d.total_strain.displacement[i].z = -0.25 * (d.total_strain.position[i].x - 4.0) / 36.0;
  }
  return d;
}

// The PNG pixel of an image pixel, where a figure placed its photograph.
std::array<int, 2> canvas_pixel(const plot::PhotoPlacement& at, double x, double y) {
  const auto p = at.device_of_pixel(x, y);
  return {static_cast<int>(std::floor(p[0] * plot::kPngPixelsPerUnit)),
          static_cast<int>(std::floor(p[1] * plot::kPngPixelsPerUnit))};
}

// Arrow red (0.80, 0.05, 0.05) or the quality figure's cross red (0.9, 0, 0), fully covered.
bool strong_red(const test::PngImage& image, int x, int y) {
  return image.red(x, y) > 180 && image.green(x, y) < 40 && image.blue(x, y) < 40;
}

// Whether a strong red pixel lies within `radius` pixels of p (anti-aliased lines cover the
// pixel of a point on them only partly).
bool red_near(const test::PngImage& image, std::array<int, 2> p, int radius) {
  for (int y = p[1] - radius; y <= p[1] + radius; ++y)
    for (int x = p[0] - radius; x <= p[0] + radius; ++x)
      if (strong_red(image, x, y)) return true;
  return false;
}

TEST(PhotoFigure, ProjectiveTransformDividesByTheThirdCoordinate) {
  // x' = x / (1 + 0.001 x), z' = (2 y + 3) / (1 + 0.001 x): at (100, 50) w = 1.1.
  const plot::PixelToPlot m{1.0, 0.0, 0.0, 0.0, 2.0, 3.0, 0.001, 0.0, 1.0};
  const auto p = plot::pixel_to_plot(m, 100.0, 50.0);
  EXPECT_NEAR(p[0], 100.0 / 1.1, 1e-12);
  EXPECT_NEAR(p[1], 103.0 / 1.1, 1e-12);
}

// The frame spans the photograph's pixel edges: x from -0.25 to 47.75 mm, z from -31.75 to 0.25 mm,
// over the canvas width less the margins (4.4 font sizes left, 150 units right).
TEST(PhotoFigure, PhotographLiesUnderTheFrameWhereTheTransformPutsIt) {
  plot::PhotoFigure figure(96, 64, half_mm_per_px, "photograph", "");
  const double frame_width = plot::kFigureWidth - 4.4 * plot::kFontSmall - 150.0;
  const plot::PlotFrame& f = figure.frame();
  EXPECT_NEAR(f.x_range().lo, -0.25, 1e-12);
  EXPECT_NEAR(f.x_range().hi, 47.75, 1e-12);
  EXPECT_NEAR(f.y_range().lo, -31.75, 1e-12);
  EXPECT_NEAR(f.y_range().hi, 0.25, 1e-12);
  EXPECT_NEAR(figure.device_per_pixel(), 0.5 * frame_width / 48.0, 1e-9);
  EXPECT_NEAR(f.pixels().h, frame_width * 32.0 / 48.0, 1e-9);
  // The affine pixel -> canvas map agrees with the frame's plot -> canvas map.
  for (const auto& [x, y] : {std::array<double, 2>{0.0, 0.0}, std::array<double, 2>{95.0, 63.0},
                             std::array<double, 2>{30.5, 12.25}}) {
    const auto plot_xy = plot::pixel_to_plot(half_mm_per_px, x, y);
    const auto device = figure.device_of_pixel(x, y);
    EXPECT_NEAR(device[0], f.px(plot_xy[0]), 1e-9);
    EXPECT_NEAR(device[1], f.py(plot_xy[1]), 1e-9);
  }
  // A photograph dark in its top-left quadrant only: dark there on the canvas, light elsewhere.
  plot::Photograph photo = uniform_photograph(230);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) photo.grey[y * 96 + x] = 20;
  figure.draw_photograph(photo, 0.0);
  const fs::path png = scratch("photo") / "photo.png";
  figure.write(png);
  const test::PngImage image = test::read_png(png);
  ASSERT_EQ(image.width, static_cast<int>(plot::kFigureWidth * plot::kPngPixelsPerUnit));
  for (const auto& [x, y, grey] : {std::array<int, 3>{10, 8, 20}, std::array<int, 3>{80, 8, 230},
                                   std::array<int, 3>{10, 56, 230}, std::array<int, 3>{80, 56, 230}}) {
    const auto p = canvas_pixel(figure.placement(), x, y);
    EXPECT_EQ(image.red(p[0], p[1]), grey) << x << ", " << y;
    EXPECT_EQ(image.blue(p[0], p[1]), grey) << x << ", " << y;
  }
}

TEST(PivFigures, QualityMarksFlaggedAndUntexturedSubsets) {
  const fs::path png = scratch("quality") / "quality.png";
  const plot::PhotoPlacement at = plot::write_piv_quality_figure(png, figure_data());
  const test::PngImage image = test::read_png(png);
  ASSERT_EQ(image.width, static_cast<int>(plot::kFigureWidth * plot::kPngPixelsPerUnit));
  // The flagged subset (column 2): a red cross through its centre.
  EXPECT_TRUE(red_near(image, canvas_pixel(at, 24.0, 8.0), 2));
  EXPECT_FALSE(red_near(image, canvas_pixel(at, 32.0, 8.0), 2));
  // Without texture (columns 0 and 1): grey 0.55 at 0.75 over the photograph's 128.
  for (double x : {8.0, 16.0}) {
    const auto p = canvas_pixel(at, x + 2.0, 10.0);
    EXPECT_NEAR(image.red(p[0], p[1]), 0.75 * 0.55 * 255 + 0.25 * 128, 2.0) << x;
    EXPECT_NEAR(image.blue(p[0], p[1]), 0.75 * 0.55 * 255 + 0.25 * 128, 2.0) << x;
  }
  // A valid subset: its ZNCC 0.95 on the viridis scale 0.6 to 1 (yellow-green: green well above blue), no cross.
  const auto valid = canvas_pixel(at, 48.0 + 2.0, 24.0 + 2.0);
  EXPECT_GT(image.green(valid[0], valid[1]), image.blue(valid[0], valid[1]) + 80);
  EXPECT_LT(image.red(valid[0], valid[1]), image.green(valid[0], valid[1]));
}

int count_arrow_pixels(const test::PngImage& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += strong_red(image, x, y);
  return n;
}

TEST(PivFigures, VectorsAreDrawnForValidSubsetsOnly) {
  const fs::path dir = scratch("vectors");
  plot::PivFigureData d = figure_data();
  const plot::PhotoPlacement at = plot::write_piv_vectors_figure(dir / "vectors.png", d);
  const test::PngImage image = test::read_png(dir / "vectors.png");
  // One arrow from each valid subset's centre in the direction of (1, 0.5) px: red a little way along it.
  EXPECT_TRUE(red_near(image, canvas_pixel(at, 40.0 + 0.6, 24.0 + 0.3), 2));
  EXPECT_FALSE(red_near(image, canvas_pixel(at, 40.0 + 0.3, 24.0 - 0.6), 2));  // across it
  EXPECT_GT(count_arrow_pixels(image), 50 * 20);
  for (auto& s : d.subsets) s.mark = SubsetMark::flagged;
  plot::write_piv_vectors_figure(dir / "none.png", d);
  EXPECT_EQ(count_arrow_pixels(test::read_png(dir / "none.png")), 0);
}

TEST(PivFigures, StrainTrianglesWhereTheSoilIsInTheImageShown) {
  const fs::path dir = scratch("strain");
  const plot::PivFigureData d = figure_data();
  const plot::PhotoPlacement at = plot::write_piv_strain_figure(dir / "total.png", d, false);
  const test::PngImage image = test::read_png(dir / "total.png");
  // A triangle's centroid moved by (0.5, -0.25) mm = (1, 0.5) px: viridis' top (0xfde725) at 0.72 over 128.
  const auto inside = canvas_pixel(at, 30.0 + 1.0, 30.0 + 0.5);
  EXPECT_NEAR(image.red(inside[0], inside[1]), 0.72 * 0xfd + 0.28 * 128, 3.0);
  EXPECT_NEAR(image.green(inside[0], inside[1]), 0.72 * 0xe7 + 0.28 * 128, 3.0);
  EXPECT_NEAR(image.blue(inside[0], inside[1]), 0.72 * 0x25 + 0.28 * 128, 3.0);
  // Just right of the last subset column (x = 80 px) but left of where it moved to (81 px): coloured.
  const auto moved = canvas_pixel(at, 80.5, 30.0);
  EXPECT_LT(image.blue(moved[0], moved[1]), 100);
  // Beyond the last subset column: the photograph alone.
  const auto outside = canvas_pixel(at, 92.0, 58.0);
  EXPECT_EQ(image.at(outside[0], outside[1]), 0x808080u);
  plot::write_piv_strain_figure(dir / "incremental.png", d, true);
  EXPECT_EQ(test::read_png(dir / "incremental.png").width, static_cast<int>(plot::kFigureWidth * plot::kPngPixelsPerUnit));
}

// Settlement (downward positive) on the diverging map, as the contour labels and the colour bar.
TEST(PivFigures, VerticalDisplacementColouredFromZeroToSettlement) {
  const fs::path png = scratch("displacement") / "w.png";
  const plot::PhotoPlacement at = plot::write_piv_vertical_displacement_figure(png, figure_data());
  const test::PngImage image = test::read_png(png);
  // Left column: no displacement, white over the faded photograph; right column: a settlement of
  // 0.25 mm, the diverging map's red end (0x67001f).
  const auto left = canvas_pixel(at, 9.0, 30.0), right = canvas_pixel(at, 79.0, 30.0);
  EXPECT_GT(image.red(left[0], left[1]), 200);
  EXPECT_GT(image.red(right[0], right[1]), image.blue(right[0], right[1]) + 30);
  EXPECT_LT(image.blue(right[0], right[1]), 100);
}

// Vector figures keep the photograph as an embedded raster image, the marks as vector paths.
TEST(PivFigures, SvgAndPdfEmbedThePhotograph) {
  const fs::path dir = scratch("formats");
  plot::write_piv_vectors_figure(dir / "vectors.svg", figure_data());
  plot::write_piv_vectors_figure(dir / "vectors.pdf", figure_data());
  std::ifstream svg_file(dir / "vectors.svg"), pdf_file(dir / "vectors.pdf", std::ios::binary);
  const std::string svg((std::istreambuf_iterator<char>(svg_file)), {}), pdf((std::istreambuf_iterator<char>(pdf_file)), {});
  EXPECT_EQ(svg.substr(0, 5), "<?xml");
  EXPECT_NE(svg.find("<image"), std::string::npos);
  EXPECT_NE(svg.find("<title>test: displacement vectors</title>"), std::string::npos);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/Subtype /Image"), std::string::npos);
}

}  // namespace
}  // namespace trapdem
