// Damaged HDF5 files (issue 14: the libhdf5 findings of the snapshot/checkpoint fuzz target). A
// variable-length string's text lives in the file's global heap, which HDF5 1.10 decodes without
// checks: each damage below made HDF5 loop for ever, allocate 2^47 bytes or copy past a buffer
// before the reader checked the heap itself (io/hdf5_global_heap). Each file is a good one with a
// few bytes changed where the HDF5 file format specification (III.E, "Global Heap") puts them;
// the readers must refuse it with a FileError naming the file and the object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "io/checkpoint.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_probe.hpp"
#include "io/snapshot.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

namespace {

std::vector<std::uint8_t> bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

void put_le(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t value, std::size_t width) {
  for (std::size_t k = 0; k < width; ++k) bytes.at(at + k) = std::uint8_t(value >> (8 * k));
}

std::size_t find(const std::vector<std::uint8_t>& bytes, const std::string& text, std::size_t from = 0) {
  const auto it = std::search(bytes.begin() + std::ptrdiff_t(from), bytes.end(), text.begin(), text.end());
  if (it == bytes.end()) throw std::runtime_error("'" + text + "' not in the file");
  return std::size_t(it - bytes.begin());
}

// Replaces the file at `path` with a copy with `change` applied to its bytes, written beside it and
// renamed over it (as another program saves a file: a new inode, so that the probe does not take it
// for the file this process wrote, io/hdf5_probe).
void damage(const std::filesystem::path& path, const std::function<void(std::vector<std::uint8_t>&)>& change) {
  std::vector<std::uint8_t> bytes = bytes_of(path);
  change(bytes);
  const std::filesystem::path copy = path.string() + ".damaged";
  write_bytes(copy, bytes);
  std::filesystem::rename(copy, path);
}

// snapshots.h5 in `dir` with `count` snapshots of one particle (each in its own file, linked).
std::filesystem::path snapshot_index(const ScratchDir& dir, int count) {
  const auto path = dir / "snapshots.h5";
  Particles p;
  p.add(1, {0.001, 0.001, 0.001}, 0.001, 2500.0);
  for (int k = 0; k < count; ++k) append_snapshot(path, make_snapshot(p, 0.1 * k, "pour", 0.001 * k, 10 * k));
  return path;
}

// A file with a string attribute "stage" = `stage` on the root and a string dataset "names"; the
// global heap collection (8-byte lengths, as HDF5 writes by default): "GCOL", version, 3
// reserved bytes, the collection's size (8 bytes) at +8, objects from +16, each an index (2), a
// reference count (2), 4 reserved bytes, its size (8) and its data padded to 8 bytes.
struct StringFile {
  std::filesystem::path path;
  std::vector<std::uint8_t> bytes;
  std::size_t heap = 0;  // offset of "GCOL"

  StringFile(const ScratchDir& dir, const std::string& stage) : path(dir / "strings.h5") {
    {
      Hdf5File f = Hdf5File::create(path);
      f.set_string_attribute("stage", stage);
      f.write_strings("names", {"floor", "trapdoor"});
      f.close();
    }
    bytes = bytes_of(path);
    heap = find(bytes, "GCOL");
  }
  // The header of the heap object holding `text`.
  std::size_t object_of(const std::string& text) const { return find(bytes, text, heap) - 16; }
  void save() const { write_bytes(path, bytes); }
};

TEST(Hdf5DamagedFile, GoodStringsStillRead) {
  ScratchDir dir;
  StringFile file(dir, "lowering");
  const Hdf5File f = Hdf5File::open_read(file.path);
  EXPECT_EQ(f.string_attribute("stage"), "lowering");
  EXPECT_EQ(f.read_strings("names"), (std::vector<std::string>{"floor", "trapdoor"}));
}

// The fuzzer's hangs: an object of index 0 (free space) and size 0 stops H5HG's decoding loop from
// advancing.
TEST(Hdf5DamagedFile, EmptyFreeSpaceObjectIsRefusedNotLoopedOn) {
  ScratchDir dir;
  StringFile file(dir, "lowering");
  const std::size_t object = file.object_of("lowering");
  put_le(file.bytes, object, 0, 2);      // index 0
  put_le(file.bytes, object + 8, 0, 8);  // size 0
  file.save();
  const Hdf5File f = Hdf5File::open_read(file.path);
  const std::string m = file_error_of([&] { f.string_attribute("stage"); });
  EXPECT_NE(m.find(file.path.string() + ": /: attribute 'stage': damaged string storage: the global heap collection "
                                        "at byte " + std::to_string(file.heap) + " holds object 0 of 0 bytes"),
            std::string::npos)
      << m;
}

// An object size near 2^64: HDF5's loop pointer wraps backwards (another endless loop).
TEST(Hdf5DamagedFile, WrappingObjectSizeIsRefused) {
  ScratchDir dir;
  StringFile file(dir, "lowering");
  put_le(file.bytes, file.object_of("lowering") + 8, ~std::uint64_t(0) - 7, 8);
  file.save();
  const Hdf5File f = Hdf5File::open_read(file.path);
  const std::string m = file_error_of([&] { f.string_attribute("stage"); });
  EXPECT_NE(m.find("which does not fit in its"), std::string::npos) << m;
}

// The fuzzer's oversized allocation: a collection claiming 2^47 bytes was allocated before HDF5
// compared it with the file.
TEST(Hdf5DamagedFile, HugeCollectionIsRefusedBeforeAllocation) {
  ScratchDir dir;
  StringFile file(dir, "lowering");
  put_le(file.bytes, file.heap + 8, std::uint64_t(1) << 47, 8);
  file.save();
  const Hdf5File f = Hdf5File::open_read(file.path);
  const std::string m = file_error_of([&] { f.string_attribute("stage"); });
  EXPECT_NE(m.find("claims 140737488355328 bytes: expected at least 16 and at most the"), std::string::npos) << m;
  EXPECT_NE(m.find(file.path.string()), std::string::npos) << m;
}

// A text longer than the string's stored length: HDF5 copies the whole object into a buffer sized
// by the length (3 bytes here, 8 copied).
TEST(Hdf5DamagedFile, TextLongerThanItsStringIsRefused) {
  ScratchDir dir;
  StringFile file(dir, "abc");
  put_le(file.bytes, file.object_of("abc") + 8, 8, 8);  // still within its 8 padded bytes
  file.save();
  const Hdf5File f = Hdf5File::open_read(file.path);
  const std::string m = file_error_of([&] { f.string_attribute("stage"); });
  EXPECT_NE(m.find("attribute 'stage': damaged string storage: a string of 3 bytes whose text in the global heap "
                   "holds 8 bytes"),
            std::string::npos)
      << m;
}

// A reference to an object the collection does not hold (HDF5 reads its table past the end).
TEST(Hdf5DamagedFile, MissingObjectIsRefusedForDatasetsToo) {
  ScratchDir dir;
  StringFile file(dir, "lowering");
  put_le(file.bytes, file.object_of("trapdoor"), 700, 2);
  file.save();
  const Hdf5File f = Hdf5File::open_read(file.path);
  EXPECT_EQ(f.string_attribute("stage"), "lowering");
  const std::string m = file_error_of([&] { f.read_strings("names"); });
  EXPECT_NE(m.find(": /names (string 1): damaged string storage: object"), std::string::npos) << m;
  EXPECT_NE(m.find("is not in the global heap collection"), std::string::npos) << m;
}

// A numeric attribute of three values read as one would be written past the one value's storage.
TEST(Hdf5DamagedFile, AttributeOfSeveralValuesIsRefused) {
  ScratchDir dir;
  const auto path = dir / "three.h5";
  {
    Hdf5File f = Hdf5File::create(path);
    const hsize_t three = 3;
    const double values[3] = {1.0, 2.0, 3.0};
    Hdf5Handle space(H5Screate_simple(1, &three, nullptr));
    Hdf5Handle attr(H5Acreate2(f.id(), "time", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
    ASSERT_GE(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, values), 0);
    attr.reset();
    f.close();
  }
  const Hdf5File f = Hdf5File::open_read(path);
  const std::string m = file_error_of([&] { f.double_attribute("time"); });
  EXPECT_NE(m.find(path.string() + ": /: attribute 'time' holds 3 values: expected one"), std::string::npos) << m;
}

// Fixed-length strings (numpy byte strings, as h5py writes them) read with their padding removed.
TEST(Hdf5DamagedFile, FixedLengthStringAttributeReads) {
  ScratchDir dir;
  const auto path = dir / "fixed.h5";
  {
    Hdf5File f = Hdf5File::create(path);
    Hdf5Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.get(), 8);
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    Hdf5Handle scalar(H5Screate(H5S_SCALAR));
    Hdf5Handle attr(H5Acreate2(f.id(), "stage", type.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT));
    const char text[8] = {'p', 'o', 'u', 'r', 0, 0, 0, 0};
    ASSERT_GE(H5Awrite(attr.get(), type.get(), text), 0);
    attr.reset();
    f.close();
  }
  EXPECT_EQ(Hdf5File::open_read(path).string_attribute("stage"), "pour");
}

// A dataset whose extent claims 2^34 doubles (128 GiB) with nothing stored: refused before the
// allocation, naming the figures.
TEST(Hdf5DamagedFile, DatasetExtentBeyondItsStorageIsRefused) {
  ScratchDir dir;
  const auto path = dir / "extent.h5";
  {
    Hdf5File f = Hdf5File::create(path);
    const hsize_t rows = hsize_t(1) << 34;
    Hdf5Handle space(H5Screate_simple(1, &rows, nullptr));
    Hdf5Handle set(H5Dcreate2(f.id(), "radius", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    ASSERT_TRUE(set.valid());
    set.reset();
    f.close();
  }
  const Hdf5File f = Hdf5File::open_read(path);
  const std::string m = file_error_of([&] { f.read_doubles("radius"); });
  EXPECT_NE(m.find(path.string() + ": /radius: its extent needs 1.37e+11 bytes in memory, but the file stores 0 "
                                   "bytes for it"),
            std::string::npos)
      << m;
}

// The three hangs the fuzzer saved (make fuzz, snapshot target): a checkpoint whose global heap
// collection is zeroed from one object to its end (objects 10 or 16 on), so that HDF5 meets an
// object of index 0 and size 0 while decoding the collection for the first attribute read
// ("format"). Rebuilt here from a checkpoint of today's writer, as those files were.
TEST(Hdf5DamagedFile, CheckpointWithZeroedHeapTailIsRefused) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  Checkpoint c;
  c.walls = {{"floor", {}, {}, {}, {}, {}}};
  c.metadata = {{"stage", "lowering"}};
  write_checkpoint(path, c);
  std::size_t heap = 0;
  damage(path, [&](std::vector<std::uint8_t>& bytes) {
    heap = find(bytes, "GCOL");
    const std::size_t size = 4096;  // HDF5's smallest collection, as the size field says:
    ASSERT_EQ(bytes.at(heap + 8) | std::size_t(bytes.at(heap + 9)) << 8, size);
    std::fill(bytes.begin() + std::ptrdiff_t(find(bytes, "floor", heap) - 16), bytes.begin() + std::ptrdiff_t(heap + size), 0);
  });
  const std::string m = file_error_of([&] { read_checkpoint(path); });
  EXPECT_NE(m.find(path.string() + ": /: attribute 'format': damaged string storage: the global heap collection at "
                                   "byte " + std::to_string(heap) + " holds object 0 of 0 bytes"),
            std::string::npos)
      << m;
}

// The snapshot fuzz target's crash of this session: snapshots.h5 with one byte of its link
// message changed (the flags, 0x08 -> 0x7e: reserved bits set, so the message does not decode).
// HDF5 1.10 lists such a group (links as messages in its header) through a table of the counted
// size and, when a message fails to decode, frees the unfilled entries' garbage pointers
// (AddressSanitizer: SEGV in free under H5G__link_release_table); Hdf5Group::children decodes
// them through a name lookup first, which fails cleanly.
TEST(Hdf5DamagedFile, SnapshotIndexWithDamagedLinkMessageIsRefused) {
  ScratchDir dir;
  const auto path = snapshot_index(dir, 1);
  damage(path, [](std::vector<std::uint8_t>& bytes) {
    // The link message: version 1, flags 0x08 (a link type follows), type 64 (external), a name of 6.
    bytes.at(find(bytes, std::string("\x01\x08\x40\x06" "000000", 10)) + 1) = 0x7e;
  });
  const std::string m = file_error_of([&] { list_snapshots(path); });
  EXPECT_NE(m.find(path.string() + ": /snapshots: cannot read the group's links (damaged link messages?)"),
            std::string::npos)
      << m;
}

// The snapshot fuzz target's second crash (harden7's run): in snapshots.h5, the /snapshots group's
// link-info message (type 2: version 0, flags 0, then the fractal heap's and the name index's
// addresses, both "undefined", all bits set, as the links are messages in the header) with the
// heap address's first byte changed, 0xff -> 0x43. The group then seems to keep its links in a
// heap at an address near 2^64, and any access to it (H5Lexists, H5Literate, H5Gget_info) goes
// H5G__obj_get_linfo -> H5B2_open -> H5F__accum_read, which copies from a null pointer: the
// process dies of SIGSEGV (AddressSanitizer or not). No HDF5 call shows that address first, so
// the readers let a child process meet the file first (io/hdf5_probe): its crash is a FileError
// naming the file, where the child was, and the signal.
TEST(Hdf5DamagedFile, LinkInfoWithAWildHeapAddressIsRefusedNotCrashedOn) {
  ScratchDir dir;
  const auto path = snapshot_index(dir, 2);
  damage(path, [](std::vector<std::uint8_t>& bytes) {
    // The message's header (type 2, size 24, flags 0, 3 reserved bytes) and its body up to the
    // first address byte; the group is the file's only one whose links are messages.
    std::vector<std::uint8_t> link_info = {0x02, 0x00, 0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
    link_info.resize(link_info.size() + 16, 0xff);
    const auto at = std::search(bytes.begin(), bytes.end(), link_info.begin(), link_info.end());
    ASSERT_NE(at, bytes.end());
    ASSERT_EQ(std::search(at + 1, bytes.end(), link_info.begin(), link_info.end()), bytes.end())
        << "a second link-info message";
    at[10] = 0x43;
  });
  const std::string m = file_error_of([&] { list_snapshots(path); });
  EXPECT_NE(m.find("libhdf5 crashed (signal 11: Segmentation fault) reading " + path.string() + ": /snapshots"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("the file is damaged"), std::string::npos) << m;
  const std::string again = file_error_of([&] { read_snapshots(path); });
  EXPECT_NE(again.find("libhdf5 crashed"), std::string::npos) << again;
}

// A file whose reading never ends (here a named pipe nobody writes to: opening it blocks, as a
// storage that does not answer or a libhdf5 loop would): the child is killed at the wall-clock
// limit and the reader says so, instead of waiting for ever.
TEST(Hdf5DamagedFile, AFileThatNeverAnswersIsRefusedAtTheTimeLimit) {
  ScratchDir dir;
  const auto path = dir / "checkpoint.h5";
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  set_hdf5_probe_limits({std::chrono::milliseconds(300), std::chrono::seconds(20), std::size_t(2) << 30});
  const std::string m = file_error_of([&] { read_checkpoint(path); });
  set_hdf5_probe_limits({});
  EXPECT_NE(m.find("libhdf5 did not finish reading " + path.string() + " within 0.3 s (the limit)"), std::string::npos)
      << m;
}

}  // namespace
