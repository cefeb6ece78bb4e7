// snapshots.h5 (an index of one file per snapshot) and its XDMF companion: appends keep earlier
// snapshots untouched, read back exactly, a failed append leaves the previous files, truncation
// drops later snapshots, the single-file layout still reads, and the XDMF references every
// non-empty snapshot.
#include "io/snapshot.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>

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
