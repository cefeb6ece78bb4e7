// `trapdem deposit` on a run folder written by the test: the snapshots before lowering are
// measured, the first lowering snapshot at 0 mm too, later ones not; deposit.json holds them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "io/snapshot.hpp"
#include "study/deposit_report.hpp"
#include "../scratch_dir.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

namespace {

// A simple cubic lattice of 2 mm spheres, 10 x 5 x 20, touching (squeezed by 1e-6).
Snapshot lattice_snapshot(const std::string& stage, double displacement) {
  const double r = 0.001, s = 2.0 * r * (1.0 - 1e-6);
  Snapshot snap;
  snap.stage = stage;
  snap.trapdoor_displacement = displacement;
  std::int64_t id = 1;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 10; ++i) {
        snap.id.push_back(id++);
        snap.position.push_back({(i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s});
        snap.radius.push_back(r);
        snap.velocity.push_back({});
        snap.angular_velocity.push_back({});
        snap.image.push_back({});
      }
  return snap;
}

// A run folder holding the lattice's resolved.toml (its snapshots added by the test).
test::ScratchDir fresh_folder(const std::string& name) {
  test::ScratchDir dir("trapdem-deposit-" + name);
  const double s = 0.002 * (1.0 - 1e-6);
  std::ofstream(dir / "resolved.toml") << "name = \"lattice\"\n[box]\nwidth = " << 10 * s << "\ndepth = " << 5 * s
                                       << "\nheight = 0.1\n[trapdoor]\nwidth = 0.004\ncentre = 0.01\ntravel = 0.002\n"
                                       << "rate = 0.01\ncavity_depth = 0.003\n";
  return dir;
}

}  // namespace

TEST(DepositReport, MeasuresTheSnapshotsBeforeTheTrapdoorMoves) {
  const test::ScratchDir dir = fresh_folder("stages");
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("pluviation", 0.0));
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("settling", 0.0));
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("lowering", 0.0));
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("lowering", 0.001));
  const auto deposits = measure_run_deposit(dir.path());
  ASSERT_EQ(deposits.size(), 3u);  // not the snapshot at 1 mm
  EXPECT_EQ(deposits[0].stage, "pluviation");
  EXPECT_EQ(deposits[2].stage, "lowering");
  for (const auto& d : deposits) EXPECT_EQ(d.metrics.particles, 1000);

  const fs::path json = write_deposit_json(dir.path(), deposits);
  std::stringstream text;
  text << std::ifstream(json).rdbuf();
  const Json doc = Json::parse(text.str(), json.string());
  ASSERT_EQ(doc["deposits"].size(), 3u);
  // The lattice's bulk: pi/6 (the lattice test in tests/analysis has the tolerance's reason).
  EXPECT_NEAR(doc["deposits"][1]["bulk_solid_fraction"].as_number(), std::numbers::pi / 6.0, 1e-4);
  EXPECT_NE(deposit_table(deposits).find("settling"), std::string::npos);
}

TEST(DepositReport, AFolderWithoutSnapshotsIsAClearError) {
  const test::ScratchDir dir = fresh_folder("empty");
  try {
    measure_run_deposit(dir.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no snapshots.h5"), std::string::npos) << e.what();
  }
  fs::remove(dir / "resolved.toml");
  EXPECT_THROW(measure_run_deposit(dir.path()), InputError);
}

// The geostatic stress at the base: the lattice's weight over the plan area, rho (pi/6) H a for a
// uniform acceleration a (the lattice's layers are a midpoint rule: exact for an acceleration linear in
// height). 1 g while settling, the g level (the default 50) from the spin-up on; in a centrifuge
// whose axis is R above the base, a(z) = omega^2 (R - z) with omega^2 R = 50 g, so the weight is
// rho (pi/6) 50 g (H - H^2 / 2R): 2 % less at H = 40 mm, R = 1 m. Tolerance 1e-5 relative: the
// lattice's squeeze of 1e-6 (tests/analysis/deposit_test.cpp).
TEST(DepositReport, TheGeostaticStressIsTheWeightOverThePlanAreaUnderTheRunsAcceleration) {
  const double s = 0.002 * (1.0 - 1e-6), height = 20 * s, rho = 2500.0, g = 9.81;
  const double phi = std::numbers::pi / 6.0 / std::pow(1.0 - 1e-6, 3);
  const test::ScratchDir dir = fresh_folder("geostatic");
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("settling", 0.0));
  append_snapshot(dir / "snapshots.h5", lattice_snapshot("lowering", 0.0));
  const auto uniform = measure_run_deposit(dir.path());
  ASSERT_EQ(uniform.size(), 2u);
  const double one_g = rho * phi * height * g;  // Pa
  EXPECT_NEAR(uniform[0].metrics.base_geostatic_stress / one_g, 1.0, 1e-5);
  EXPECT_NEAR(uniform[1].metrics.base_geostatic_stress / (50.0 * one_g), 1.0, 1e-5);
  // Halfway up (the profile's slabs are 5 diameters: 10 layers below z = 10 s, the second slab's
  // lower face), half the weight.
  ASSERT_GE(uniform[1].metrics.profile.size(), 3u);
  EXPECT_NEAR(uniform[1].metrics.profile[2].z_low, 10 * s, 1e-6);
  EXPECT_NEAR(uniform[1].metrics.profile[2].geostatic_stress / (25.0 * one_g), 1.0, 1e-5);

  const double radius = 1.0;  // m, from the axis to the base
  std::ofstream(dir / "resolved.toml", std::ios::app)
      << "[centrifuge]\nradius = " << radius << "\nreference = \"base\"\neuler = false\n";
  const auto frame = measure_run_deposit(dir.path());
  EXPECT_NEAR(frame[0].metrics.base_geostatic_stress / one_g, 1.0, 1e-5);  // settling: 1 g, before the spin
  const double expected = rho * phi * 50.0 * g * (height - height * height / (2.0 * radius));
  EXPECT_NEAR(frame[1].metrics.base_geostatic_stress / expected, 1.0, 1e-5);
  EXPECT_NE(deposit_table(frame).find("sigma_v0 kPa"), std::string::npos);
}
