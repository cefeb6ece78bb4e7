// snapshots.h5 (an index of one file per snapshot) and its XDMF companion: appends keep earlier
// snapshots untouched, read back exactly, a failed append leaves the previous files, truncation
// drops later snapshots, the single-file layout still reads, and the XDMF references every
// non-empty snapshot. A run of clumps adds each particle's body and the bodies.
#include "io/snapshot.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dem/rigid/clump_shapes.hpp"
#include "dem/simulation.hpp"
#include "io/hdf5_file.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

namespace {

Particles some_particles(std::size_t n, double shift) {
  Particles p;
  for (std::size_t i = 0; i < n; ++i)
    p.add(std::int64_t(100 + i), {0.001 * double(i) + shift, -0.002 * double(i), 0.5 + shift}, 0.001 + 1e-5 * double(i),
          2500.0, {0.1 * double(i), 0.0, -shift}, {0.0, 3.0 * double(i), 0.0});
  if (n > 1) p.image[1] = {0, -1, 0};
  return p;
}

void expect_same(const Snapshot& a, const Snapshot& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.stage, b.stage);
  EXPECT_EQ(a.trapdoor_displacement, b.trapdoor_displacement);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.radius, b.radius);
  ASSERT_EQ(a.position.size(), b.position.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position[i], b.position[i]);
    EXPECT_EQ(a.velocity[i], b.velocity[i]);
    EXPECT_EQ(a.angular_velocity[i], b.angular_velocity[i]);
    EXPECT_EQ(a.image[i].y, b.image[i].y);
  }
}

std::vector<std::string> names_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

ino_t inode_of(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return 0;
  return st.st_ino;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(Snapshots, AppendListReadAndXdmf) {
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  const Snapshot empty = make_snapshot(Particles{}, 0.0, "pluviation", 0.0, 0);
  const Snapshot first = make_snapshot(some_particles(5, 0.0), 1.5, "settling", 0.0, 1500);
  const Snapshot second = make_snapshot(some_particles(7, 0.01), 2.25, "lowering & <done>", 0.005, 2250);
  EXPECT_EQ(append_snapshot(path, empty), "000000");
  EXPECT_EQ(append_snapshot(path, first), "000001");
  EXPECT_EQ(append_snapshot(path, second), "000002");

  const std::vector<SnapshotInfo> list = list_snapshots(path);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[1].name, "000001");
  EXPECT_EQ(list[1].particle_count, 5u);
  EXPECT_EQ(list[2].stage, "lowering & <done>");
  EXPECT_EQ(list[2].trapdoor_displacement, 0.005);
  EXPECT_EQ(list[2].step, 2250);

  const std::vector<Snapshot> all = read_snapshots(path);
  ASSERT_EQ(all.size(), 3u);
  expect_same(all[0], empty);
  expect_same(all[1], first);
  expect_same(all[2], second);

  // Units are stated in the file for h5py users.
  const Hdf5File f = Hdf5File::open_read(path);
  EXPECT_EQ(f.string_attribute("format"), "trapdem-snapshots");

  const std::string xmf = read_all(dir / "snapshots.xmf");
  EXPECT_NE(xmf.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  EXPECT_NE(xmf.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_EQ(count(xmf, "GridType=\"Uniform\""), 2u) << "the empty snapshot is left out";
  EXPECT_NE(xmf.find("NumberOfElements=\"7\""), std::string::npos);
  EXPECT_NE(xmf.find("Dimensions=\"7 3\""), std::string::npos);
  EXPECT_NE(xmf.find(">snapshots/000002.h5:/position</DataItem>"), std::string::npos) << xmf;
  EXPECT_NE(xmf.find(">snapshots/000001.h5:/radius</DataItem>"), std::string::npos);
  EXPECT_NE(xmf.find("<Time Value=\"2.25\"/>"), std::string::npos);
  // ParaView makes cells (what its default view draws) only from an explicit vertex list: the
  // first N entries of /vertex_index, 0, 1, 2, ...
  EXPECT_EQ(f.read_uint32s("vertex_index"), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(count(xmf, "ItemType=\"HyperSlab\" Dimensions=\"5\""), 1u) << xmf;
  EXPECT_EQ(count(xmf, ">0 1 7</DataItem>"), 1u);
  EXPECT_EQ(count(xmf, "NumberType=\"UInt\" Precision=\"4\" Format=\"HDF\">snapshots.h5:/vertex_index<"), 2u);
  EXPECT_NE(xmf.find("lowering &amp; &lt;done&gt;"), std::string::npos);
  EXPECT_EQ(dir.entry_count(), 3u);  // snapshots.h5, snapshots.xmf, snapshots/: no temporaries
  EXPECT_EQ(names_in(dir / "snapshots"), (std::vector<std::string>{"000000.h5", "000001.h5", "000002.h5"}));
}

TEST(Snapshots, AnAppendLeavesTheEarlierSnapshotsFilesAsTheyWere) {
  // The point of one file per snapshot: an append writes the new snapshot and a small index, not
  // a copy of everything before it.
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  append_snapshot(path, make_snapshot(some_particles(2000, 0.0), 1.0, "settling", 0.0, 10));
  const std::string first_file = read_all(dir / "snapshots" / "000000.h5");
  const auto first_inode = inode_of(dir / "snapshots" / "000000.h5");
  for (int k = 1; k <= 3; ++k)
    append_snapshot(path, make_snapshot(some_particles(2000, 0.001 * k), 1.0 + k, "lowering", 0.001 * k, 10 + k));
  EXPECT_EQ(inode_of(dir / "snapshots" / "000000.h5"), first_inode) << "replaced by a copy";
  EXPECT_EQ(read_all(dir / "snapshots" / "000000.h5"), first_file);
  // The index holds links and the vertex index, not particle data: far smaller than a snapshot.
  EXPECT_LT(std::filesystem::file_size(path), std::filesystem::file_size(dir / "snapshots" / "000000.h5") / 4);
  EXPECT_EQ(list_snapshots(path).size(), 4u);
}

TEST(Snapshots, TruncationDropsTheLaterSnapshotsAndTheirFiles) {
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  std::vector<Snapshot> written;
  for (int k = 0; k < 4; ++k) {
    written.push_back(make_snapshot(some_particles(4 + k, 0.001 * k), 1.0 + k, "lowering", 0.001 * k, 100 * k));
    append_snapshot(path, written.back());
  }
  truncate_snapshots(path, 250);  // keeps steps 0, 100, 200
  const std::vector<Snapshot> kept = read_snapshots(path);
  ASSERT_EQ(kept.size(), 3u);
  for (std::size_t k = 0; k < kept.size(); ++k) expect_same(kept[k], written[k]);
  EXPECT_EQ(names_in(dir / "snapshots"), (std::vector<std::string>{"000000.h5", "000001.h5", "000002.h5"}));
  const std::string xmf = read_all(dir / "snapshots.xmf");
  EXPECT_EQ(count(xmf, "GridType=\"Uniform\""), 3u);
  EXPECT_EQ(xmf.find("000003"), std::string::npos);
  // The resumed run's next snapshot takes the freed name.
  EXPECT_EQ(append_snapshot(path, written[3]), "000003");
  expect_same(read_snapshot(path, "000003"), written[3]);

  truncate_snapshots(path, 1000);  // nothing later: unchanged
  EXPECT_EQ(list_snapshots(path).size(), 4u);
  truncate_snapshots(path, -1);    // nothing kept: no index, no XDMF, no snapshot files
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(dir / "snapshots.xmf"));
  EXPECT_TRUE(names_in(dir / "snapshots").empty());
}

TEST(Snapshots, AppendsToAnIndexWhoseSnapshotsAreGroupsInside) {
  // A file in the single-file layout (another tool's, or trapdem's before format version 2):
  // appends add linked files, and readers and the XDMF take both kinds.
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  const Snapshot old = make_snapshot(some_particles(3, 0.0), 1.0, "settling", 0.0, 10);
  {
    Hdf5File f = Hdf5File::create(path);
    const Hdf5Group g = f.create_group("snapshots").create_group("000000");
    g.write_int64s("id", old.id);
    g.write_vec3s("position", old.position);
    g.write_vec3s("velocity", old.velocity);
    g.write_vec3s("angular_velocity", old.angular_velocity);
    g.write_doubles("radius", old.radius);
    g.write_int3s("image", old.image);
    g.set_double_attribute("time", old.time);
    g.set_string_attribute("stage", old.stage);
    g.set_double_attribute("trapdoor_displacement", old.trapdoor_displacement);
    g.set_int_attribute("step", old.step);
    f.close();
  }
  const Snapshot later = make_snapshot(some_particles(6, 0.01), 2.0, "lowering", 0.002, 20);
  EXPECT_EQ(append_snapshot(path, later), "000001");
  const std::vector<Snapshot> all = read_snapshots(path);
  ASSERT_EQ(all.size(), 2u);
  expect_same(all[0], old);
  expect_same(all[1], later);
  const std::string xmf = read_all(dir / "snapshots.xmf");
  EXPECT_NE(xmf.find(">snapshots.h5:/snapshots/000000/position</DataItem>"), std::string::npos) << xmf;
  EXPECT_NE(xmf.find(">snapshots/000001.h5:/position</DataItem>"), std::string::npos) << xmf;
}

TEST(Snapshots, FailedAppendKeepsThePreviousFile) {
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  append_snapshot(path, make_snapshot(some_particles(3, 0.0), 1.0, "settling", 0.0, 10));
  const auto size_before = std::filesystem::file_size(path);
  {
    FileSizeLimit limit(size_before + 4096);  // room for the copy, not for 20 000 more particles
    EXPECT_THROW(append_snapshot(path, make_snapshot(some_particles(20000, 0.0), 2.0, "lowering", 0.01, 20)),
                 FileError);
  }
  const std::vector<SnapshotInfo> list = list_snapshots(path);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].particle_count, 3u);
  EXPECT_EQ(dir.entry_count(), 3u);
  EXPECT_EQ(names_in(dir / "snapshots"), (std::vector<std::string>{"000000.h5"}));  // no temporary left
}

TEST(Snapshots, ReadsAMinimalFileWrittenByAnotherTool) {
  // What docs/output.md promises: id, position and radius suffice.
  ScratchDir dir;
  const auto path = dir / "mine.h5";
  {
    Hdf5File f = Hdf5File::create(path);
    const Hdf5Group g = f.create_group("snapshots").create_group("000000");
    g.write_int64s("id", std::vector<std::int64_t>{1, 2});
    g.write_vec3s("position", std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
    g.write_doubles("radius", std::vector<double>{0.5, 0.5});
    g.set_double_attribute("trapdoor_displacement", 0.02);
    f.close();
  }
  const Snapshot s = read_snapshot(path, "000000");
  EXPECT_EQ(s.size(), 2u);
  EXPECT_EQ(s.trapdoor_displacement, 0.02);
  EXPECT_EQ(s.velocity.size(), 2u);
  EXPECT_EQ(s.stage, "");
}

namespace {

// Six clumps (sub-angular grains and dimers, 2 mm) dropped onto a floor, run long enough for list
// rebuilds to re-order the particles, so that rows are neither in member nor in id order.
Simulation small_clump_run() {
  const ClumpTemplate grain =
      make_clump_template(sub_angular_members(5, 0.6, 1.3, 0.9), "grain").scaled_to(0.002);
  const ClumpTemplate dimer = make_clump_template(dimer_members(1.5), "dimer").scaled_to(0.002);
  Particles p;
  RigidBodies bodies;
  std::int64_t member_id = 1;
  for (int k = 0; k < 6; ++k) {
    const ClumpTemplate& shape = k % 2 ? dimer : grain;
    const Vec3 centre{0.003 * (k % 3), 0.003 * (k / 3), 0.0015 + 0.0007 * k};
    add_rigid_body(bodies, p, 60 - 10 * k, member_id, shape, 2500.0, centre, Quaternion::about_axis({0.6, 0.0, 0.8}, 0.4 * k),
                   {0.0, 0.0, -0.05}, {10.0 * k, -5.0, 3.0});
    member_id += std::int64_t(shape.members.size());
  }
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.001};
  s.domain.upper = {0.02, 0.02, 0.02};
  s.reorder_every = 1;
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.tangential_stiffness = 0.5e4;
  law.restitution = 0.3;
  law.static_friction = 0.5;
  law.kinetic_friction = 0.4;
  Simulation sim(std::move(p), law, s, std::move(bodies));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.set_gravity(Vec3{0.0, 0.0, -50.0 * 9.81});
  return sim;
}

}  // namespace

// A snapshot of a run of clumps holds each particle's body id and the bodies' centres of mass,
// velocities, orientations and angular velocities, read back bit for bit; the XDMF gives ParaView
// the body id as a particle attribute. A snapshot of spheres in the same file has neither.
TEST(Snapshots, ARunOfClumpsRecordsEachParticlesBodyAndTheBodies) {
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  Simulation sim = small_clump_run();
  sim.run(2000);
  ASSERT_GT(sim.stats().rebuilds, 1);
  const Particles& p = sim.particles();
  ASSERT_FALSE(std::is_sorted(p.id.begin(), p.id.end())) << "rows re-ordered in space";
  const RigidBodies& bodies = sim.bodies();
  append_snapshot(path, make_snapshot(some_particles(4, 0.0), 0.5, "settling", 0.0, 10));
  append_snapshot(path, make_snapshot(p, bodies, sim.time(), "pluviation", 0.0, sim.step_count()));

  const Snapshot spheres = read_snapshot(path, "000000");
  EXPECT_TRUE(spheres.body.empty());
  EXPECT_TRUE(spheres.bodies.empty());

  const Snapshot s = read_snapshot(path, "000001");
  ASSERT_EQ(s.size(), p.size());
  ASSERT_EQ(s.body.size(), p.size());
  // Each row's body, found independently: the body whose members list the row's particle id.
  std::size_t wrong_body = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::int64_t expected = kNoBodyId;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m)
        if (bodies.member_id[m] == s.id[i]) expected = bodies.id[b];
    wrong_body += s.body[i] != expected || expected == kNoBodyId;
  }
  EXPECT_EQ(wrong_body, 0u);
  ASSERT_EQ(s.bodies.size(), 6u);
  EXPECT_EQ(s.bodies.id, bodies.id);
  EXPECT_EQ(s.bodies.position, bodies.position);
  EXPECT_EQ(s.bodies.velocity, bodies.velocity);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Quaternion& q = s.bodies.orientation[b];
    const Quaternion& r = bodies.orientation[b];
    EXPECT_TRUE(q.w == r.w && q.x == r.x && q.y == r.y && q.z == r.z) << "body " << bodies.id[b];
    EXPECT_EQ(s.bodies.angular_velocity[b], bodies.angular_velocity(b)) << "body " << bodies.id[b];
  }
  EXPECT_GT(norm(s.bodies.angular_velocity[3]), 0.0) << "the bodies turn";

  // The grains as the analysis follows them: a row per body, its volume-equivalent radius
  // (3 V / 4 pi)^(1/3) of the union's volume, its centre of mass and motion.
  const Snapshot grains = grain_view(s);
  ASSERT_EQ(grains.size(), bodies.size());
  EXPECT_EQ(grains.id, bodies.id);
  EXPECT_EQ(grains.position, bodies.position);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    EXPECT_DOUBLE_EQ(grains.radius[b], std::cbrt(3.0 * bodies.volume[b] / (4.0 * std::numbers::pi)));
  EXPECT_EQ(grains.stage, s.stage);
  EXPECT_EQ(grain_view(spheres).id, spheres.id) << "a snapshot of spheres is its own grains";

  // The layout docs/output.md gives h5py users: an int64 column per particle, a group per snapshot.
  const Hdf5File f = Hdf5File::open_read(dir / "snapshots" / "000001.h5");
  EXPECT_EQ(f.dataset_length("body"), p.size());
  const Hdf5Group g = f.group("bodies");
  for (const char* name : {"id", "position", "radius", "velocity", "orientation", "angular_velocity"})
    EXPECT_EQ(g.dataset_length(name), 6u) << name;

  const std::string xmf = read_all(dir / "snapshots.xmf");
  EXPECT_EQ(count(xmf, "<Attribute Name=\"body\" AttributeType=\"Scalar\""), 1u) << "the clumps' snapshot only";
  EXPECT_EQ(count(xmf, ">snapshots/000001.h5:/body</DataItem>"), 1u) << xmf;
  EXPECT_EQ(count(xmf, ">snapshots/000000.h5:/body</DataItem>"), 0u);
}

// A particle's body that is none of the snapshot's bodies is damage, named with its row.
TEST(Snapshots, AParticlesUnknownBodyIsRefused) {
  ScratchDir dir;
  const auto path = dir / "snapshots.h5";
  Simulation sim = small_clump_run();
  Snapshot s = make_snapshot(sim.particles(), sim.bodies(), 0.0, "pluviation", 0.0, 0);
  s.body[2] = 12345;
  append_snapshot(path, s);
  const std::string m = file_error_of([&] { read_snapshot(path, "000000"); });
  EXPECT_NE(m.find("000000"), std::string::npos) << m;
  EXPECT_NE(m.find(fmt::format("row 2 (particle id {}): body 12345", s.id[2])), std::string::npos) << m;
}
