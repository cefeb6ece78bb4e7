// Checkpoints: a run resumed from a checkpoint continues bit for bit as the run that went straight
// through (of spheres, and of rigid clumps at 1 and 3 threads); a failed write keeps the previous
// checkpoint; a mismatched simulation or a damaged file is refused.
#include "io/checkpoint.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <omp.h>
#include <unistd.h>

#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/rigid/clump_shapes.hpp"
#include "io/hdf5_file.hpp"
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

// A run whose skin was changed (an experiment's pour has its own): the checkpoint keeps the skin
// its lists were built with, so a resume whose owner sets the skin again only after the restore
// (as TrapdoorExperiment::restore does) checks the lists against the right one: bit for bit.
TEST(Checkpoint, TheListsSkinSurvivesAResume) {
  ScratchDir dir;
  const auto path = dir / "skin.h5";
  Simulation straight = settling_box();
  const double built_with = straight.skin();
  straight.run(1500);
  straight.set_skin(3.0 * built_with);
  const std::int64_t rebuilds = straight.stats().rebuilds;
  straight.run(1500);
  ASSERT_GT(straight.stats().rebuilds, rebuilds) << "no list built with the new skin before the checkpoint";
  ASSERT_EQ(straight.list_state().skin_at_build, 3.0 * built_with);
  save_checkpoint(path, straight);
  straight.run(2000);

  Simulation resumed = settling_box();  // the skin of its settings until its owner sets it
  restore_checkpoint(resumed, read_checkpoint(path));
  EXPECT_EQ(resumed.list_state().skin_at_build, 3.0 * built_with);
  resumed.set_skin(3.0 * built_with);
  resumed.run(2000);
  expect_bitwise_equal(straight, resumed);
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

namespace {

// Clumps (issue 39): irregular grains and dimers of 2 mm volume-equivalent diameter falling into an
// 11 mm box under 50 g, with friction, so that the bodies' state, the members' contact histories
// and the lists are all at stake.
constexpr double kClumpDiameter = 0.002;  // m, volume-equivalent
constexpr double kClumpDensity = 2500.0;  // kg/m^3
constexpr double kClumpHalf = 0.0055;     // m, half width of the box
constexpr double kClumpTimeStep = 4e-6;   // s, fixed: a pour starts without particles

ContactLaw clump_law() {
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.tangential_stiffness = 0.5e4;
  law.restitution = 0.3;
  law.static_friction = 0.5;
  law.kinetic_friction = 0.4;
  law.rolling_friction = 0.0;  // clumps stand in for rolling resistance (rigid_bodies.hpp)
  law.rolling_model = RollingModel::none;
  return law;
}

const ClumpTemplate& grain_shape() {
  static const ClumpTemplate shape =
      make_clump_template(sub_angular_members(5, 0.6, 1.3, 0.9), "grain").scaled_to(kClumpDiameter);
  return shape;
}

const ClumpTemplate& dimer_shape() {
  static const ClumpTemplate shape = make_clump_template(dimer_members(1.5), "dimer").scaled_to(kClumpDiameter);
  return shape;
}

// Body k of the pour: its shape, centre (a 3 x 3 column of 3.2 mm cells, 4 layers from 2.5 mm up),
// orientation and motion, all from a jitter seeded by k, so that every run builds it alike.
struct BodyPlacement {
  const ClumpTemplate* shape;
  Vec3 position, velocity, angular_velocity;
  Quaternion orientation;
};
BodyPlacement placement(int k) {
  std::uint64_t rng = 1000 + std::uint64_t(k);
  const int ix = k % 3, iy = (k / 3) % 3, layer = k / 9;
  BodyPlacement b;
  b.shape = k % 3 == 1 ? &dimer_shape() : &grain_shape();
  b.position = {-0.0032 + 0.0032 * ix + 2e-4 * jitter(rng), -0.0032 + 0.0032 * iy + 2e-4 * jitter(rng),
                0.0025 + 0.0032 * layer};
  Vec3 axis{jitter(rng), jitter(rng), 0.3 + jitter(rng)};
  b.orientation = Quaternion::about_axis(axis / norm(axis), 6.0 * jitter(rng));
  b.velocity = {0.05 * jitter(rng), 0.05 * jitter(rng), -0.1};
  b.angular_velocity = {40 * jitter(rng), 40 * jitter(rng), 40 * jitter(rng)};
  return b;
}

// Body ids count down and member ids up from 5000, so that neither follows the particles' order.
std::int64_t clump_body_id(int k) { return 100 - k; }
std::int64_t clump_member_id(int k) { return 5000 + 10 * k; }

void add_clump(Simulation& sim, int k) {
  const BodyPlacement b = placement(k);
  sim.add_body(clump_body_id(k), clump_member_id(k), *b.shape, kClumpDensity, b.position, b.orientation, b.velocity,
               b.angular_velocity);
}

// The box with its first `bodies` clumps (0: an empty box, a pour adds them with add_body).
Simulation clump_box(int bodies) {
  Particles p;
  RigidBodies rigid;
  for (int k = 0; k < bodies; ++k) {
    const BodyPlacement b = placement(k);
    add_rigid_body(rigid, p, clump_body_id(k), clump_member_id(k), *b.shape, kClumpDensity, b.position, b.orientation,
                   b.velocity, b.angular_velocity);
  }
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.001};
  s.domain.upper = {0.01, 0.01, 0.04};
  s.time_step = kClumpTimeStep;
  s.skin = 3e-4;
  const ContactLaw law = clump_law();
  Simulation sim(std::move(p), law, s, std::move(rigid));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("x-", {-kClumpHalf, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {kClumpHalf, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, -kClumpHalf, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, kClumpHalf, 0}, {0, -1, 0}, law));
  sim.set_gravity(Vec3{0.0, 0.0, -50.0 * 9.81});
  return sim;
}

bool same_orientation(const Quaternion& a, const Quaternion& b) {
  return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

// The particles as expect_bitwise_equal, and every body's state.
void expect_clumps_bitwise_equal(const Simulation& a, const Simulation& b) {
  expect_bitwise_equal(a, b);
  const RigidBodies& p = a.bodies();
  const RigidBodies& q = b.bodies();
  ASSERT_EQ(p.size(), q.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    differing += !(p.id[k] == q.id[k] && p.position[k] == q.position[k] && p.velocity[k] == q.velocity[k] &&
                   same_orientation(p.orientation[k], q.orientation[k]) &&
                   p.angular_momentum[k] == q.angular_momentum[k] && p.force[k] == q.force[k] &&
                   p.torque[k] == q.torque[k]);
  EXPECT_EQ(differing, 0u) << "bodies whose state differs after the resume";
}

// Sets the OpenMP thread count for a scope and restores the one before (the test programs run on
// one thread, tests/one_thread_environment.cpp).
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : before_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~ThreadCount() { omp_set_num_threads(before_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int before_;
};

}  // namespace

// 36 clumps fall into the box and pile up; the run is checkpointed once they touch, and the resumed
// run (a box built again with the same bodies, the checkpoint restored into it) ends where the run
// that went straight through does: every member sphere, every body's centre, velocity,
// orientation and angular momentum bit for bit, at 1 and at 3 threads.
TEST(CheckpointClumps, ResumedClumpRunIsBitwiseIdenticalAtOneAndThreeThreads) {
  constexpr std::int64_t K = 3000, M = 2000;
  for (const int threads : {1, 3}) {
    SCOPED_TRACE(fmt::format("{} threads", threads));
    const ThreadCount scope(threads);
    ScratchDir dir;
    const auto path = dir / "checkpoint.h5";
    Simulation straight = clump_box(36);
    ASSERT_LT(straight.time_step(), 0.3 * straight.critical_time_step()) << "the fixed step is stable";
    straight.run(K);
    ASSERT_GT(straight.contact_count(), 20u) << "the clumps touch: their members' contact history is at stake";
    save_checkpoint(path, straight, {{"stage", "pluviation"}});
    const std::int64_t rebuilds_at_checkpoint = straight.stats().rebuilds;
    straight.run(M);
    ASSERT_GT(straight.stats().rebuilds, rebuilds_at_checkpoint) << "lists are rebuilt after the resume";

    Simulation resumed = clump_box(36);
    Checkpoint c = read_checkpoint(path);
    ASSERT_EQ(c.bodies.size(), 36u);
    EXPECT_EQ(c.bodies.member_count(), c.particles.size()) << "every particle a member";
    restore_checkpoint(resumed, std::move(c));
    resumed.run(M);
    expect_clumps_bitwise_equal(straight, resumed);
  }
}

// Every array of the bodies' state is written and read back bit for bit; the derived arrays are not
// state and come back empty.
TEST(CheckpointClumps, BodiesRoundTripBitForBit) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  Simulation sim = clump_box(12);
  sim.run(500);
  const Checkpoint written = capture_checkpoint(sim);
  write_checkpoint(path, written);
  const Checkpoint read = read_checkpoint(path);
  const RigidBodies& a = written.bodies;
  const RigidBodies& b = read.bodies;
  ASSERT_EQ(b.size(), 12u);
  EXPECT_EQ(b.id, a.id);
  EXPECT_EQ(b.mass, a.mass);
  EXPECT_EQ(b.principal_inertia, a.principal_inertia);
  EXPECT_EQ(b.position, a.position);
  EXPECT_EQ(b.velocity, a.velocity);
  ASSERT_EQ(b.orientation.size(), a.orientation.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(same_orientation(b.orientation[k], a.orientation[k])) << k;
  EXPECT_EQ(b.angular_momentum, a.angular_momentum);
  EXPECT_EQ(b.force, a.force);
  EXPECT_EQ(b.torque, a.torque);
  EXPECT_EQ(b.first_member, a.first_member);
  EXPECT_EQ(b.member_id, a.member_id);
  EXPECT_EQ(b.member_offset, a.member_offset);
  EXPECT_TRUE(b.member_particle.empty() && b.body_of_particle.empty()) << "derived, not state";
}

// A pour, as the experiment's pluviation does it: the box starts empty and bodies are added as the
// run goes. The checkpoint is taken just after an add_body (the lists are stale until the next
// step's rebuild, in both runs) and restored into an empty box, which takes its bodies from it;
// a body added after the resume joins both runs alike. And a checkpoint of a box that never
// stepped: its first step still does the initial set-up (placing the members, the first forces).
TEST(CheckpointClumps, ResumeOfAPourAndBeforeTheFirstStep) {
  ScratchDir dir;
  {
    const auto path = dir / "pour.h5";
    Simulation straight = clump_box(0);
    for (int k = 0; k < 10; ++k) {
      add_clump(straight, k);
      straight.run(200);
    }
    add_clump(straight, 10);
    save_checkpoint(path, straight);
    straight.run(200);
    add_clump(straight, 11);
    straight.run(2000);
    ASSERT_GT(straight.contact_count(), 0u) << "the second layer lands on the first";
    ASSERT_LT(straight.wall(0).force.z, 0.0) << "and the first on the floor";

    Simulation resumed = clump_box(0);
    restore_checkpoint(resumed, read_checkpoint(path));
    ASSERT_EQ(resumed.bodies().size(), 11u);
    resumed.run(200);
    add_clump(resumed, 11);
    resumed.run(2000);
    expect_clumps_bitwise_equal(straight, resumed);
  }
  {
    const auto path = dir / "fresh.h5";
    Simulation straight = clump_box(20);
    save_checkpoint(path, straight);
    straight.run(800);
    Simulation resumed = clump_box(20);
    restore_checkpoint(resumed, read_checkpoint(path));
    resumed.run(800);
    expect_clumps_bitwise_equal(straight, resumed);
  }
}

// A run of spheres writes no bodies group and reads back without bodies (as a checkpoint written
// before checkpoints held bodies does); a simulation built with bodies refuses such a checkpoint.
TEST(CheckpointClumps, ARunOfSpheresHasNoBodiesGroup) {
  ScratchDir dir;
  const auto path = dir / "spheres.h5";
  Simulation sim = settling_box();
  sim.run(10);
  save_checkpoint(path, sim);
  EXPECT_FALSE(Hdf5File::open_read(path).has("bodies"));
  const Checkpoint c = read_checkpoint(path);
  EXPECT_TRUE(c.bodies.empty());
  EXPECT_EQ(c.particles.size(), sim.particles().size());

  const auto clumps = dir / "clumps.h5";
  Simulation with_bodies = clump_box(4);
  with_bodies.run(10);
  save_checkpoint(clumps, with_bodies);
  EXPECT_TRUE(Hdf5File::open_read(clumps).has("bodies"));
  Checkpoint without_bodies = read_checkpoint(clumps);
  without_bodies.bodies = RigidBodies{};
  Simulation other = clump_box(4);
  try {
    restore_checkpoint(other, std::move(without_bodies));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no rigid bodies"), std::string::npos) << e.what();
  }
}

// A damaged bodies group is named: a missing dataset (file and dataset), a member that is not among
// the particles, a quaternion that is not a rotation (file, group and body id).
TEST(CheckpointClumps, DamagedBodiesAreRefusedNamingTheFileAndDataset) {
  ScratchDir dir;
  Simulation sim = clump_box(4);
  sim.run(10);
  {
    const auto path = dir / "missing.h5";
    save_checkpoint(path, sim);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, "bodies/orientation", H5P_DEFAULT), 0);
    H5Fclose(file);
    const std::string m = file_error_of([&] { read_checkpoint(path); });
    EXPECT_NE(m.find(path.string()), std::string::npos) << m;
    EXPECT_NE(m.find("bodies/orientation"), std::string::npos) << m;
  }
  struct Damage {
    const char* expected;
    std::size_t body;  // the row the message names
    void (*damage)(Checkpoint&);
  };
  const Damage damages[] = {
      {"is not among the particles", 0, [](Checkpoint& c) { c.bodies.member_id[1] = 999999; }},  // body 0's second
      {"expected a unit quaternion", 1, [](Checkpoint& c) { c.bodies.orientation[1].w = 2.0; }},
      {"principal_inertia", 1, [](Checkpoint& c) { c.bodies.principal_inertia[1].y = 0.0; }},
  };
  for (const Damage& d : damages) {
    SCOPED_TRACE(d.expected);
    Checkpoint c = capture_checkpoint(sim);
    d.damage(c);
    const auto path = dir / "damaged.h5";
    write_checkpoint(path, c);
    const std::string m = file_error_of([&] { read_checkpoint(path); });
    EXPECT_NE(m.find(path.string()), std::string::npos) << m;
    EXPECT_NE(m.find("/bodies"), std::string::npos) << m;
    EXPECT_NE(m.find(d.expected), std::string::npos) << m;
    EXPECT_NE(m.find(fmt::format("row {} (body id {})", d.body, c.bodies.id[d.body])), std::string::npos) << m;
  }
}
