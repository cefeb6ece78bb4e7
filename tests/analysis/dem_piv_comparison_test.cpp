// DEM against PIV on one grid (src/analysis/dem_piv_comparison.hpp): the common grid, the RMS error
// over the common area, the snapshot index in a rendered image's name. Reading piv.h5 as the PIV
// module writes it: tests/piv/piv_h5_reading_test.cpp; two folders compared: tests/study.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/dem_piv_comparison.hpp"
#include "core/errors.hpp"

namespace trapdem {
namespace {

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

}  // namespace
}  // namespace trapdem
