// snapshots.h5 after a kill in the middle of an append (SIGKILL: no handler, no unwinding): the
// index still opens and every snapshot it lists reads back exactly as written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "io/snapshot.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;
namespace fs = std::filesystem;

namespace {

// Snapshot k, recognisable from k alone. 40 000 particles (about 4.6 MB): an append takes long
// enough that a kill at a varying moment lands inside one most of the time.
Snapshot snapshot_number(int k) {
  Particles p;
  const std::size_t n = 40000;
  for (std::size_t i = 0; i < n; ++i)
    p.add(std::int64_t(i), {0.001 * double(i), 0.0001 * k, 0.5}, 0.001, 2500.0, {0.0, 0.0, -0.01 * k}, {double(k), 0.0, 0.0});
  return make_snapshot(p, 0.1 * k, "lowering", 0.001 * k, 1000 * k);
}

void expect_snapshot_number(const Snapshot& s, int k) {
  const Snapshot expected = snapshot_number(k);
  EXPECT_EQ(s.time, expected.time);
  EXPECT_EQ(s.step, expected.step);
  ASSERT_EQ(s.size(), expected.size());
  EXPECT_EQ(s.id, expected.id);
  EXPECT_EQ(s.radius, expected.radius);
  for (std::size_t i = 0; i < s.size(); ++i) {
    ASSERT_EQ(s.position[i], expected.position[i]) << "snapshot " << k << " row " << i;
    ASSERT_EQ(s.velocity[i], expected.velocity[i]);
    ASSERT_EQ(s.angular_velocity[i], expected.angular_velocity[i]);
  }
}

// A temporary left by process `pid` anywhere under `dir`: the kill came in the middle of a write.
bool temporary_of(const fs::path& dir, pid_t pid) {
  const std::string mark = ".tmp-" + std::to_string(pid) + "-";
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(mark) != std::string::npos) return true;
  return false;
}

// Waits (up to ~60 s) until the live process `pid` is inside a write: a temporary of its own
// exists. Entries come and go while it writes, so the walk tolerates them vanishing.
bool wait_for_a_write(const fs::path& dir, pid_t pid) {
  const std::string mark = ".tmp-" + std::to_string(pid) + "-";
  for (int poll = 0; poll < 60000; ++poll) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename().string().find(mark) != std::string::npos) return true;
    ::usleep(1000);
  }
  return false;
}

}  // namespace

TEST(SnapshotsAfterAKill, TheIndexStillOpensWithEveryEarlierSnapshot) {
  ScratchDir dir;
  const fs::path path = dir / "snapshots.h5";
  append_snapshot(path, snapshot_number(0));
  int kills_mid_write = 0;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::size_t before = list_snapshots(path).size();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {  // appends until killed
      try {
        for (int k = int(before);; ++k) append_snapshot(path, snapshot_number(k));
      } catch (...) {
      }
      ::_exit(3);
    }
    // The kill follows the child's first write by a varying delay (none on even attempts, which
    // then land inside a write whatever the host's load; 5-35 ms on odd ones, which fall in other
    // phases of an append: the snapshot's own file, the index, the XDMF, or between them). Whether
    // a kill fell inside a write is read from the temporaries it left, not from timing.
    ASSERT_TRUE(wait_for_a_write(dir.path(), child)) << "the child never started a write";
    if (attempt % 2 == 1) ::usleep(5000 * attempt);
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child stopped by itself (status " << status << ")";
    if (temporary_of(dir.path(), child)) ++kills_mid_write;

    const std::vector<SnapshotInfo> infos = list_snapshots(path);
    ASSERT_GE(infos.size(), before);
    for (std::size_t k = 0; k < infos.size(); ++k) {
      EXPECT_EQ(infos[k].name, fmt::format("{:06d}", k));
      expect_snapshot_number(read_snapshot(path, infos[k].name), int(k));
    }
    // The next append carries on after whatever the kill left (a temporary, a snapshot file
    // not yet in the index).
    append_snapshot(path, snapshot_number(int(infos.size())));
  }
  EXPECT_GT(kills_mid_write, 0) << "no kill fell inside a write: the test proved nothing";
  std::printf("%d of 8 kills fell inside a write\n", kills_mid_write);
  const std::size_t n = list_snapshots(path).size();
  expect_snapshot_number(read_snapshot(path, fmt::format("{:06d}", n - 1)), int(n - 1));
}
