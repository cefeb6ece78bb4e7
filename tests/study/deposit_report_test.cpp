// `trapdem deposit` on a run folder written by the test: the snapshots before lowering are
// measured, the first lowering snapshot at 0 mm too, later ones not; deposit.json holds them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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
