// The probe in a child process that HDF5 files from users pass before a reader opens them
// (io/hdf5_probe, io/hdf5_walk). The damaged files it stops are in hdf5_damaged_file_test.cpp; here,
// good files it must let through.
#include <gtest/gtest.h>

#include "io/hdf5_file.hpp"
#include "io/hdf5_probe.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

namespace {

// Two files whose external links lead to each other (h5py writes such pairs): the probe lets them
// through within a short CPU limit instead of going round the circle, and the reader reads through
// the link. (libhdf5 1.10 itself already stops this circle, so this guards the probe's accepting
// such files; its own guards, objects and files entered once, are for circles HDF5 follows.)
TEST(Hdf5Probe, ExternalLinksInACircleAreLetThrough) {
  ScratchDir dir;
  for (const auto& [self, other] : {std::pair{"a.h5", "b.h5"}, std::pair{"b.h5", "a.h5"}}) {
    Hdf5File f = Hdf5File::create(dir / self);
    f.create_group("data").write_doubles("x", std::vector<double>{1.0, 2.0});
    f.create_external_link("other", other, "/");
    f.close();
  }
  set_hdf5_probe_limits({std::chrono::milliseconds(20000), std::chrono::seconds(5), std::size_t(2) << 30});
  EXPECT_NO_THROW(probe_hdf5_file(dir / "a.h5"));
  set_hdf5_probe_limits({});
  const Hdf5File a = Hdf5File::open_read(dir / "a.h5");
  EXPECT_EQ(a.group("other").group("data").read_doubles("x"), (std::vector<double>{1.0, 2.0}));
}

// A file that is not HDF5 at all: the probe has nothing to say (HDF5 refuses to open it, cleanly),
// so the reader's own message is the one the user sees.
TEST(Hdf5Probe, AFileThatIsNotHdf5GetsTheReadersMessage) {
  ScratchDir dir;
  const auto path = dir / "notes.h5";
  std::ofstream(path) << "not an HDF5 file\n";
  EXPECT_NO_THROW(probe_hdf5_file(path));
  const std::string m = file_error_of([&] { Hdf5File::open_read(path); });
  EXPECT_NE(m.find(path.string() + ": cannot open as an HDF5 file"), std::string::npos) << m;
}

}  // namespace
