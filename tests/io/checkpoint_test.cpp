// Checkpoints: a run resumed from a checkpoint continues bit for bit as the run that went straight
// through; a failed write keeps the previous checkpoint; a mismatched simulation is refused.
#include "io/checkpoint.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>

#include "core/errors.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

namespace {

constexpr double kHalf = 0.005;  // m, half width of the box

// splitmix64: deterministic jitter independent of the standard library.
double jitter(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return double((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0) - 0.5;  // [-0.5, 0.5)
}

// 200 spheres (0.6-0.8 mm) on a jittered lattice, ids in reverse order so that the spatial
// re-ordering moves them, falling into a 10 mm box with a lid that moves down: friction and EPSD
// rolling springs make the contact history matter, the lid makes the wall state matter. Under 50 g.
Simulation settling_box() {
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.tangential_stiffness = 0.5e4;
  law.restitution = 0.3;
  law.static_friction = 0.5;
  law.kinetic_friction = 0.4;
  law.rolling_friction = 0.1;
  law.rolling_model = RollingModel::elastic_plastic;
  Particles p;
  std::uint64_t rng = 11;
  std::int64_t id = 200;
  for (int layer = 0; layer < 8; ++layer)
    for (int ix = 0; ix < 5; ++ix)
      for (int iy = 0; iy < 5; ++iy)
        p.add(id--,
              {-0.0034 + 0.0017 * ix + 2e-4 * jitter(rng), -0.0034 + 0.0017 * iy + 2e-4 * jitter(rng),
               0.001 + 0.0017 * layer},
              0.0007 + 2e-4 * jitter(rng), 2500.0);
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.001};
  s.domain.upper = {0.01, 0.01, 0.06};
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("x-", {-kHalf, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {kHalf, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, -kHalf, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, kHalf, 0}, {0, -1, 0}, law));
  Wall lid = Wall::rectangle("lid", {0, 0, 0.03}, {1, 0, 0}, kHalf, {0, 1, 0}, kHalf, law);
  lid.velocity = [](double t) { return Vec3{0.0, 0.0, -0.2 * t}; };  // accelerating: the time matters
  sim.add_wall(std::move(lid));
  sim.set_gravity(Vec3{0.0, 0.0, -50.0 * 9.81});  // the centrifuge's 50 g: the bed forms within a few ms
  return sim;
}

void expect_bitwise_equal(const Simulation& a, const Simulation& b) {
  const Particles& p = a.particles();
  const Particles& q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.stats().steps, b.stats().steps);
  EXPECT_EQ(a.stats().rebuilds, b.stats().rebuilds);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    differing += !(p.id[i] == q.id[i] && p.position[i] == q.position[i] && p.velocity[i] == q.velocity[i] &&
                   p.angular_velocity[i] == q.angular_velocity[i] && p.force[i] == q.force[i]);
  }
  EXPECT_EQ(differing, 0u) << "particles whose state differs after the resume";
  for (std::size_t k = 0; k < a.walls().size(); ++k) {
    EXPECT_EQ(a.walls()[k].force, b.walls()[k].force) << a.walls()[k].name;
    EXPECT_EQ(a.walls()[k].origin, b.walls()[k].origin) << a.walls()[k].name;
  }
}

}  // namespace

TEST(Checkpoint, ResumedRunIsBitwiseIdentical) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  constexpr std::int64_t K = 4000, M = 3000;
  Simulation straight = settling_box();
  straight.run(K);
  ASSERT_GT(straight.contact_count(), 50u) << "the bed has formed: contact history is at stake";
  save_checkpoint(path, straight, {{"stage", "settling"}, {"progress", "0.5"}});
  const std::int64_t rebuilds_at_checkpoint = straight.stats().rebuilds;
  straight.run(M);
  ASSERT_GT(straight.stats().rebuilds, rebuilds_at_checkpoint) << "lists are rebuilt after the resume";

  Simulation resumed = settling_box();
  Checkpoint c = read_checkpoint(path);
  EXPECT_EQ(c.metadata.at("stage"), "settling");
  EXPECT_EQ(c.metadata.at("progress"), "0.5");
  EXPECT_EQ(c.stats.steps, K);
  restore_checkpoint(resumed, std::move(c));
  resumed.run(M);
  expect_bitwise_equal(straight, resumed);
}

TEST(Checkpoint, ResumeAfterParticlesWereAddedAndBeforeTheFirstStep) {
  ScratchDir dir;
  // Added particles: the lists are stale until the next step's rebuild, in both runs.
  {
    const auto path = dir / "added.h5";
    Simulation straight = settling_box();
    straight.run(1000);
    straight.add_particle(1000, {0.0, 0.0, 0.02}, 0.0007, 2500.0, {0.0, 0.0, -0.1});
    save_checkpoint(path, straight);
    straight.run(1000);
    Simulation resumed = settling_box();
    restore_checkpoint(resumed, read_checkpoint(path));
    resumed.run(1000);
    expect_bitwise_equal(straight, resumed);
  }
  // Never stepped: the resumed one still does the initial force set-up.
  {
    const auto path = dir / "fresh.h5";
    Simulation straight = settling_box();
    save_checkpoint(path, straight);
    straight.run(500);
    Simulation resumed = settling_box();
    restore_checkpoint(resumed, read_checkpoint(path));
    resumed.run(500);
    expect_bitwise_equal(straight, resumed);
  }
}

TEST(Checkpoint, FailedWriteKeepsThePreviousCheckpoint) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  Simulation sim = settling_box();
  sim.run(200);
  save_checkpoint(path, sim, {{"stage", "first"}});
  sim.run(200);
  try {
    FileSizeLimit limit(8 * 1024);  // a disk that fills up during the write
    save_checkpoint(path, sim, {{"stage", "second"}});
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  const Checkpoint kept = read_checkpoint(path);
  EXPECT_EQ(kept.stats.steps, 200);
  EXPECT_EQ(kept.metadata.at("stage"), "first");
  EXPECT_EQ(dir.entry_count(), 1u) << "no temporary left behind";

  // A folder that cannot be written.
  const auto nowhere = dir / "missing-folder" / "checkpoint.h5";
  try {
    save_checkpoint(nowhere, sim);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(nowhere.string()), std::string::npos) << e.what();
  }
  if (::geteuid() != 0) {  // root ignores folder permissions
    std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    EXPECT_THROW(save_checkpoint(path, sim), FileError);
    std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_all);
    EXPECT_EQ(read_checkpoint(path).stats.steps, 200);
  }
}

TEST(Checkpoint, RefusesAMismatchedSimulationOrFile) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  Simulation sim = settling_box();
  sim.run(10);
  save_checkpoint(path, sim);

  Simulation fewer_walls = settling_box();
  {
    Particles p = sim.particles();
    SimulationSettings s = sim.settings();
    Simulation other(std::move(p), sim.particle_law(), s);
    other.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, sim.particle_law()));
    EXPECT_THROW(restore_checkpoint(other, read_checkpoint(path)), InputError);
  }
  {
    SimulationSettings s = sim.settings();
    s.time_step = 0.5 * sim.time_step();
    Simulation other(sim.particles(), sim.particle_law(), s);
    for (const Wall& w : sim.walls()) other.add_wall(w);
    try {
      restore_checkpoint(other, read_checkpoint(path));
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("time step"), std::string::npos) << e.what();
    }
  }
  std::ofstream(dir / "junk.h5") << "junk";
  EXPECT_THROW(read_checkpoint(dir / "junk.h5"), FileError);
}
