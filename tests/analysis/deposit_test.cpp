// The deposit metrics against cases with exact answers: a simple cubic lattice (solid fraction
// pi/6, six neighbours inside), sphere caps, the surface height, contacts across a periodic depth.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/deposit.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

constexpr double kRadius = 0.001;  // m

// nx x ny x nz spheres at spacing s = 2 r (1 - squeeze) (every neighbour overlaps by 2 r squeeze),
// the first centre at s / 2 from each side.
Snapshot lattice(int nx, int ny, int nz, double squeeze) {
  const double s = 2.0 * kRadius * (1.0 - squeeze);
  Snapshot snap;
  std::int64_t id = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        snap.id.push_back(id++);
        snap.position.push_back({(i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s});
        snap.radius.push_back(kRadius);
      }
  const std::size_t n = snap.id.size();
  snap.velocity.assign(n, Vec3{});
  snap.angular_velocity.assign(n, Vec3{});
  snap.image.assign(n, Int3{});
  return snap;
}

}  // namespace

TEST(Deposit, SphereVolumeBelowAPlaneIsTheCapVolume) {
  const double r = 2.0, whole = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_EQ(sphere_volume_below(0.0, r, -2.5), 0.0);
  EXPECT_NEAR(sphere_volume_below(0.0, r, 2.5), whole, 1e-12 * whole);
  EXPECT_NEAR(sphere_volume_below(0.0, r, 0.0), 0.5 * whole, 1e-12 * whole);
  // A cap of height 1 of a sphere of radius 2: pi h^2 (3 r - h) / 3 = 5 pi / 3.
  EXPECT_NEAR(sphere_volume_below(0.0, r, -1.0), 5.0 * std::numbers::pi / 3.0, 1e-12);
}

TEST(Deposit, SimpleCubicLatticeHasSolidFractionPiOverSixAndSixNeighboursInside) {
  const int nx = 12, ny = 4, nz = 30;
  const double squeeze = 1e-6, s = 2.0 * kRadius * (1.0 - squeeze);
  DepositSettings settings;
  settings.box_width = nx * s;
  settings.box_depth = ny * s;
  settings.bin_height = 5.0 * s;  // whole lattice layers: each slab holds five layers
  const DepositMetrics m = measure_deposit(lattice(nx, ny, nz, squeeze), settings);

  EXPECT_EQ(m.particles, nx * ny * nz);
  EXPECT_NEAR(m.mean_diameter, 2.0 * kRadius, 1e-15);
  // The sphere volume per lattice cell, pi/6 (2r/s)^3; a sphere pokes r - s/2 = r squeeze out of its
  // cell, so a slab boundary moves ~1e-6 of the volume: tolerance 1e-5.
  const double expected = std::numbers::pi / 6.0 / std::pow(1.0 - squeeze, 3);
  // Six slabs of five layers, and a seventh holding the sliver (r squeeze) of the top layer above
  // 30 s: the profile reaches the highest top.
  ASSERT_EQ(m.profile.size(), std::size_t(nz / 5 + 1));
  for (int k = 0; k < nz / 5; ++k) {
    EXPECT_NEAR(m.profile[k].solid_fraction, expected, 1e-5) << "slab from " << m.profile[k].z_low;
    EXPECT_EQ(m.profile[k].particles, 5 * nx * ny);
  }
  EXPECT_LT(m.profile.back().solid_fraction, 1e-9);
  EXPECT_EQ(m.profile.back().particles, 0);
  // Every top is (nz - 1/2) s + r.
  EXPECT_NEAR(m.surface_height, (nz - 0.5) * s + kRadius, 1e-12);
  EXPECT_NEAR(m.surface_roughness, 0.0, 1e-9);
  // The bulk layer leaves out 5 d at the base and below the surface: there every particle has both
  // vertical neighbours and, on average, 2 (n - 1) / n in each horizontal direction (the side walls).
  EXPECT_NEAR(m.bulk_z_low, 5.0 * 2.0 * kRadius, 1e-15);
  EXPECT_NEAR(m.bulk_coordination, 2.0 + 2.0 * (nx - 1.0) / nx + 2.0 * (ny - 1.0) / ny, 1e-12);
  EXPECT_EQ(m.bulk_rattler_fraction, 0.0);
  EXPECT_NEAR(m.bulk_solid_fraction, expected, 1e-4);
  // Every neighbour pair overlaps by 2 r squeeze, i.e. squeeze of r_i + r_j.
  EXPECT_EQ(m.contacts, long((nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1)));
  EXPECT_NEAR(m.mean_overlap, squeeze, 1e-9);
  EXPECT_NEAR(m.max_overlap, squeeze, 1e-9);  // not whole layers at its ends
}

TEST(Deposit, SpheresThatDoNotOverlapAreNotInContact) {
  DepositSettings settings;
  settings.box_width = 12 * 2.2 * kRadius;
  settings.box_depth = 4 * 2.2 * kRadius;
  const DepositMetrics m = measure_deposit(lattice(12, 4, 30, -0.1), settings);  // gaps of 0.2 r
  EXPECT_EQ(m.bulk_coordination, 0.0);
  EXPECT_EQ(m.bulk_rattler_fraction, 1.0);
}

TEST(Deposit, ContactsAcrossAPeriodicDepthCountOnlyWhenPeriodic) {
  // One column of three spheres along y in a depth of three spacings: the first and last touch
  // across y = 0 / depth only on a periodic axis.
  const double squeeze = 1e-3, s = 2.0 * kRadius * (1.0 - squeeze);
  Snapshot snap = lattice(1, 3, 1, squeeze);
  DepositSettings settings;
  settings.box_width = s;
  settings.box_depth = 3.0 * s;
  settings.base_margin = 0.0;
  settings.surface_margin = -1.0;  // the bulk layer from the base to one diameter above the top
  EXPECT_NEAR(measure_deposit(snap, settings).bulk_coordination, 4.0 / 3.0, 1e-12);
  settings.periodic_depth = true;
  EXPECT_NEAR(measure_deposit(snap, settings).bulk_coordination, 2.0, 1e-12);
}

TEST(Deposit, BadInputIsAClearError) {
  DepositSettings settings;
  settings.box_width = 0.01;
  settings.box_depth = 0.01;
  EXPECT_THROW(measure_deposit(Snapshot{}, settings), InputError);
  Snapshot outside = lattice(2, 2, 2, 0.0);
  outside.position[3].x = 0.5;
  try {
    measure_deposit(outside, settings);
    FAIL() << "a particle outside the box was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("particle 4"), std::string::npos) << e.what();
  }
  settings.box_width = 0.0;
  EXPECT_THROW(measure_deposit(lattice(2, 2, 2, 0.0), settings), InputError);
}

// Without a density and an acceleration the deposit gives no stress (NaN, null in deposit.json)
// rather than a made-up one; with them, the weight above each slab's lower face.
TEST(Deposit, TheGeostaticStressNeedsADensityAndAnAcceleration) {
  const int nx = 6, ny = 3, nz = 10;
  const double squeeze = 1e-6, s = 2.0 * kRadius * (1.0 - squeeze);
  DepositSettings settings;
  settings.box_width = nx * s;
  settings.box_depth = ny * s;
  settings.bin_height = 5.0 * s;
  const Snapshot snap = lattice(nx, ny, nz, squeeze);
  const DepositMetrics none = measure_deposit(snap, settings);
  EXPECT_TRUE(std::isnan(none.base_geostatic_stress));
  EXPECT_TRUE(std::isnan(none.profile[0].geostatic_stress));
  settings.solid_density = 1000.0;
  settings.downward_acceleration = [](const Vec3&) { return 10.0; };
  const DepositMetrics m = measure_deposit(snap, settings);
  // Each layer weighs rho (4/3 pi r^3) a per sphere; tolerance 1e-5: the squeeze (test above).
  const double layer = nx * ny * 1000.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) * 10.0 /
                       (settings.box_width * settings.box_depth);  // Pa
  EXPECT_NEAR(m.base_geostatic_stress / (nz * layer), 1.0, 1e-5);
  EXPECT_NEAR(m.profile[1].geostatic_stress / (5 * layer), 1.0, 1e-5);
}

namespace {

// `snap` with its spheres paired along x into two-member bodies (spheres 2k and 2k + 1 of each row,
// nx even), each body a sphere of `body_radius` at the pair's midpoint in the bodies' table.
Snapshot paired_into_bodies(Snapshot snap, double body_radius) {
  for (std::size_t i = 0; i < snap.size(); i += 2) {
    const std::int64_t body = 1000 + std::int64_t(i / 2);
    snap.body.push_back(body);
    snap.body.push_back(body);
    snap.bodies.id.push_back(body);
    snap.bodies.position.push_back(0.5 * (snap.position[i] + snap.position[i + 1]));
    snap.bodies.radius.push_back(body_radius);
    snap.bodies.velocity.push_back({});
    snap.bodies.orientation.push_back({});
    snap.bodies.angular_velocity.push_back({});
  }
  return snap;
}

}  // namespace

// A snapshot of clumps is measured by its grains (issue 39): one dimer of two spheres of radius r
// whose centres are r apart, alone in its box: one grain, no contact (its members overlap by
// design), its mean diameter the volume-equivalent one, and its weight the union's,
// 2 (4/3 pi r^3) - 5 pi r^3 / 12 (the lens of two spheres of radius r at distance r is
// pi (4 r + r)(2 r - r)^2 / 12): 27/32 of the members' sum. Exact up to round-off.
TEST(Deposit, AClumpIsOneGrainOfItsUnionsVolumeWithoutContactsWithinIt) {
  const double r = kRadius;
  const double union_volume = 2.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r - 5.0 * std::numbers::pi * r * r * r / 12.0;
  const double r_eq = std::cbrt(3.0 * union_volume / (4.0 * std::numbers::pi));
  Snapshot snap;
  snap.id = {1, 2};
  snap.position = {{0.005 - 0.5 * r, 0.002, r}, {0.005 + 0.5 * r, 0.002, r}};
  snap.radius = {r, r};
  snap.velocity.assign(2, Vec3{});
  snap.angular_velocity.assign(2, Vec3{});
  snap.image.assign(2, Int3{});
  snap = paired_into_bodies(snap, r_eq);
  DepositSettings settings;
  settings.box_width = 0.01;
  settings.box_depth = 0.004;
  settings.solid_density = 1000.0;
  settings.downward_acceleration = [](const Vec3&) { return 10.0; };
  const DepositMetrics m = measure_deposit(snap, settings);
  EXPECT_EQ(m.particles, 1);
  EXPECT_EQ(m.contacts, 0);
  EXPECT_EQ(m.max_overlap, 0.0);
  EXPECT_NEAR(m.mean_diameter, 2.0 * r_eq, 1e-15);
  EXPECT_NEAR(m.base_geostatic_stress, 1000.0 * 10.0 * union_volume / (0.01 * 0.004), 1e-9);
  EXPECT_NEAR(m.surface_height, 2.0 * r, 1e-15) << "the members' tops";
}

// The simple cubic lattice with its spheres paired along x into bodies: every contact but the one
// within each pair stays, and a grain counts its members' contacts with other grains. Over the
// whole deposit (the bulk layer widened to all of it) the mean per grain is then exactly twice
// the spheres' mean less 2.
TEST(Deposit, AClumpsContactsAreItsMembersContactsWithOtherClumps) {
  const int nx = 12, ny = 4, nz = 30;
  const double squeeze = 1e-4, s = 2.0 * kRadius * (1.0 - squeeze);
  DepositSettings settings;
  settings.box_width = nx * s;
  settings.box_depth = ny * s;
  settings.base_margin = 0.0;
  settings.surface_margin = -1.0;  // from the base to a diameter above the top: every grain
  const Snapshot spheres = lattice(nx, ny, nz, squeeze);
  const DepositMetrics as_spheres = measure_deposit(spheres, settings);
  const Snapshot clumps = paired_into_bodies(spheres, std::cbrt(2.0) * kRadius);
  const DepositMetrics m = measure_deposit(clumps, settings);
  EXPECT_EQ(m.particles, nx * ny * nz / 2);
  EXPECT_EQ(m.contacts, as_spheres.contacts - nx * ny * nz / 2);
  EXPECT_DOUBLE_EQ(m.max_overlap, as_spheres.max_overlap);
  EXPECT_NEAR(m.bulk_coordination, 2.0 * as_spheres.bulk_coordination - 2.0, 1e-12);
  EXPECT_GT(m.bulk_coordination, 7.0);
}
