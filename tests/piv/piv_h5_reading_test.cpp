// piv.h5 as the PIV module writes it (write_piv_h5) read back by the comparison with DEM
// (read_piv_vertical_displacement, src/analysis/dem_piv_comparison.hpp): model coordinates in m
// about the trapdoor centre, the displacement from a reference image, the step as the spacing.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include "analysis/dem_piv_comparison.hpp"
#include "core/errors.hpp"
#include "piv/piv_output.hpp"
#include "../scratch_dir.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

// A linear settlement field (m, w < 0 down) of the trapdoor displacement delta.
double settlement_w(Point2 p, double delta) { return -delta * (0.8 - 2.0 * (p.z - 0.02) + 1.5 * (p.x - 0.1)); }

// A 0.5 mm/px camera over a 0.2 m wide box (pixel (0, 0) at model (0, 140) mm), subsets every 8 px
// moved by the settlement field.
void write_synthetic_piv(const fs::path& file, const std::vector<double>& deltas) {
  const double s = 0.5;  // mm per px
  PivResult r;
  r.grid.subset_size = 16;
  r.grid.step = 8;
  for (int y = 8; y <= 272; y += 8) {
    for (int x = 8; x <= 392; x += 8) r.grid.centre.push_back({double(x), double(y)});
  }
  r.grid.columns = 49;
  r.grid.rows = static_cast<int>(r.grid.centre.size()) / 49;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < deltas.size(); ++k) {
    names.push_back(fmt::format("/somewhere/camera/{:03d}_{:g}mm.png", k, deltas[k] * 1e3));
    ImageMeasurements im;
    for (const auto& c : r.grid.centre) {
      SubsetMeasurement m;
      const Point2 p{c.x * s * 1e-3, (140.0 - c.y * s) * 1e-3};  // m, box coordinates
      m.u = 0.0;
      m.v = deltas[k] > 0.0 ? -settlement_w(p, deltas[k]) * 1e3 / s : 0.0;
      m.zncc = 1.0;
      m.status = SubsetStatus::valid;
      im.subset.push_back(m);
    }
    r.image.push_back(im);
  }
  r.reference_images = {0};
  write_piv_h5(file, r, names, scale_transform(s, {0.0, 140.0 / s}), "mm", PivStrainSeries{});
}

TEST(PivH5Reading, VerticalDisplacementInModelCoordinatesAboutTheTrapdoorCentre) {
  const test::ScratchDir dir("trapdem-piv-h5-reading");
  write_synthetic_piv(dir / "piv.h5", {0.0, 0.005, 0.01});
  ASSERT_EQ(piv_image_names(dir / "piv.h5").size(), 3u);
  EXPECT_EQ(piv_image_names(dir / "piv.h5")[2], "/somewhere/camera/002_10mm.png");
  const auto f = read_piv_vertical_displacement(dir / "piv.h5", 1, 3, {0.1, 0.0});
  ASSERT_EQ(f.position.size(), 49u * 34u);
  EXPECT_NEAR(f.spacing, 0.004, 1e-12);
  EXPECT_NEAR(f.position[0].x, 0.004 - 0.1, 1e-12);
  EXPECT_NEAR(f.position[0].z, 0.136, 1e-12);
  EXPECT_NEAR(f.w[0], settlement_w({0.004, 0.136}, 0.01), 1e-12);
  // From image 2 to 3: the increment, at the positions in image 2.
  const auto g = read_piv_vertical_displacement(dir / "piv.h5", 2, 3, {0.1, 0.0});
  EXPECT_NEAR(g.w[0], settlement_w({0.004, 0.136}, 0.01) - settlement_w({0.004, 0.136}, 0.005), 1e-12);
  EXPECT_THROW(read_piv_vertical_displacement(dir / "piv.h5", 1, 4), InputError);
  EXPECT_THROW(piv_image_names(dir / "missing.h5"), InputError);
}

}  // namespace
}  // namespace trapdem
