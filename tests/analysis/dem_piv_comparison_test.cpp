// trapdem compare: DEM and PIV vertical displacement on one grid and the RMS error over the common
// area (src/analysis/dem_piv_comparison.hpp, apps/compare_command.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <optional>

#include "analysis/dem_piv_comparison.hpp"
#include "compare_command.hpp"
#include "core/errors.hpp"
#include "piv/piv_output.hpp"
#include "synthetic_run.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

// A linear settlement field (exact under linear interpolation on any triangulation): w < 0 down.
double settlement_w(Point2 p, double delta) { return -delta * (0.8 - 2.0 * (p.z - 0.02) + 1.5 * (p.x - 0.1)); }

ScatteredDisplacement lattice_field(double x0, double x1, double z0, double z1, double h, double offset) {
  ScatteredDisplacement f;
  f.spacing = h;
  for (double z = z0; z <= z1 + 1e-12; z += h) {
    for (double x = x0; x <= x1 + 1e-12; x += h) {
      f.position.push_back({x, z});
      f.w.push_back(settlement_w({x, z}, 0.01) + offset);
    }
  }
  return f;
}

TEST(DemPivComparison, CommonGridIsTheOverlapOnMultiplesOfTheSpacing) {
  const GridSpec g = common_grid({{-0.05, 0.0}, {0.05, 0.1}}, {{-0.031, 0.011}, {0.2, 0.3}}, 0.002);
  EXPECT_NEAR(g.x0, -0.030, 1e-12);
  EXPECT_NEAR(g.z0, 0.012, 1e-12);
  EXPECT_NEAR(g.x(g.nx - 1), 0.05, 1e-12);
  EXPECT_NEAR(g.z(g.nz - 1), 0.1, 1e-12);
  EXPECT_THROW(common_grid({{0.0, 0.0}, {0.01, 0.01}}, {{0.02, 0.0}, {0.03, 0.01}}, 0.002), InputError);
  EXPECT_THROW(common_grid({{0.0, 0.0}}, {{0.0, 0.0}}, 0.0), InputError);
}

TEST(DemPivComparison, IdenticalFieldsGiveZeroAndAnOffsetGivesItsRms) {
  const auto dem = lattice_field(-0.06, 0.06, 0.002, 0.1, 0.002, 0.0);
  const auto same = lattice_field(-0.05, 0.07, 0.004, 0.12, 0.004, 0.0);
  const auto shifted = lattice_field(-0.05, 0.07, 0.004, 0.12, 0.004, 0.0003);
  const GridSpec grid = common_grid(dem.position, same.position, 0.002);
  const GridField a = interpolate_scattered(dem, grid);
  const FieldComparison zero = compare_fields(a, interpolate_scattered(same, grid), 0.01);
  EXPECT_GT(zero.compared, 1000u);
  EXPECT_NEAR(zero.coverage, 1.0, 1e-12);
  EXPECT_LT(zero.rms, 1e-12);
  const FieldComparison off = compare_fields(a, interpolate_scattered(shifted, grid), 0.01);
  EXPECT_NEAR(off.rms, 0.0003, 1e-12);
  EXPECT_NEAR(off.bias, -0.0003, 1e-12);
  EXPECT_NEAR(off.rms_normalised(), 0.03, 1e-10);
  // A grid node outside one field is not compared; no common node is an error.
  GridField b = interpolate_scattered(same, grid);
  for (double& v : b.value) v = std::nan("");
  EXPECT_THROW(compare_fields(a, b, 0.01), InputError);
}

TEST(DemPivComparison, RenderedImageNamesGiveTheSnapshotIndex) {
  EXPECT_EQ(rendered_snapshot_index("/tmp/run/camera/004_10mm.png"), 4);
  EXPECT_EQ(rendered_snapshot_index("000_0mm.png"), 0);
  EXPECT_EQ(rendered_snapshot_index("012_2.5mm.png"), 12);
  EXPECT_EQ(rendered_snapshot_index("IMG_0004.JPG"), -1);
  EXPECT_EQ(rendered_snapshot_index("image_001.png"), -1);
}

// piv.h5 written by the PIV module's own writer: a 0.5 mm/px camera over the synthetic box
// (pixel (0, 0) at model (0, 140) mm), subsets every 8 px moved by the settlement field (+ offset).
void write_synthetic_piv(const fs::path& dir, const std::vector<double>& deltas, double offset_m) {
  fs::create_directories(dir);
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
      const double w = deltas[k] > 0.0 ? settlement_w(p, deltas[k]) + offset_m : 0.0;
      m.u = 0.0;
      m.v = -w * 1e3 / s;
      m.zncc = 1.0;
      m.status = SubsetStatus::valid;
      im.subset.push_back(m);
    }
    r.image.push_back(im);
  }
  r.reference_images = {0};
  write_piv_h5(dir / "piv.h5", r, names, scale_transform(s, {0.0, 140.0 / s}), "mm", PivStrainSeries{});
}

TEST(DemPivComparison, ReadsPivH5InModelCoordinatesAboutTheTrapdoorCentre) {
  const fs::path dir = fs::temp_directory_path() / "trapdem_cmp_read";
  fs::remove_all(dir);
  write_synthetic_piv(dir, {0.0, 0.005, 0.01}, 0.0);
  ASSERT_EQ(piv_image_names(dir / "piv.h5").size(), 3u);
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
  fs::remove_all(dir);
}

struct CompareCase {
  fs::path run, piv;
};

CompareCase make_case(const std::string& name, double offset_m) {
  const fs::path root = fs::temp_directory_path() / name;
  fs::remove_all(root);
  const std::vector<double> deltas{0.0, 0.005, 0.01};
  test::make_synthetic_run(root / "run", deltas,
                           [](Point2 p, double delta) { return Point2{0.0, settlement_w(p, delta)}; });
  write_synthetic_piv(root / "piv", deltas, offset_m);
  return {root / "run", root / "piv"};
}

TEST(DemPivComparison, SameFieldGivesZeroAndAnOffsetFieldItsKnownRmsThroughTheCommand) {
  const CompareCase same = make_case("trapdem_cmp_same", 0.0);
  CompareOptions o;
  o.dem_dir = same.run.string();
  o.piv_dir = same.piv.string();
  o.at = "10mm";
  const CompareResult c = compare_directories(o);
  EXPECT_EQ(c.piv_image, 3u);
  EXPECT_EQ(c.piv_reference_image, 1u);
  EXPECT_NEAR(c.trapdoor_travel(), 0.01, 1e-9);
  EXPECT_GT(c.error.compared, 2000u);
  EXPECT_GT(c.error.coverage, 0.9);
  EXPECT_LT(c.error.rms_normalised(), 1e-6);

  const CompareCase off = make_case("trapdem_cmp_offset", 0.0002);  // PIV 0.2 mm higher everywhere
  o.dem_dir = off.run.string();
  o.piv_dir = off.piv.string();
  o.out = (off.run / "compare.png").string();
  const CompareResult d = compare_directories(o);
  EXPECT_NEAR(d.error.rms_normalised(), 0.02, 1e-6);
  EXPECT_NEAR(d.error.bias_normalised(), -0.02, 1e-6);
  EXPECT_EQ(app::run_compare(o), 0);
  EXPECT_TRUE(fs::exists(off.run / "compare.png"));

  // --image picks another image: 5 mm of PIV against 10 mm of DEM is far off.
  o.image = 2;
  EXPECT_GT(compare_directories(o).error.rms_normalised(), 0.2);
  o.image = 0;

  // Clear errors: unknown displacement, missing PIV, no overlap.
  o.at = "7mm";
  EXPECT_THROW(compare_directories(o), InputError);
  o.at = "10mm";
  o.piv_trapdoor = "900mm,0mm";
  EXPECT_THROW(compare_directories(o), InputError);
  o.piv_trapdoor.clear();
  o.piv_dir = (off.run / "nothing").string();
  EXPECT_THROW(compare_directories(o), InputError);
  fs::remove_all(same.run.parent_path());
  fs::remove_all(off.run.parent_path());
}

}  // namespace
}  // namespace trapdem
