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

#include "io/checkpoint.hpp"
#include "io/hdf5_file.hpp"
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

// Rewrites the file at `path` with `change` applied to its bytes.
void damage(const std::filesystem::path& path, const std::function<void(std::vector<std::uint8_t>&)>& change) {
  std::vector<std::uint8_t> bytes = bytes_of(path);
  change(bytes);
  write_bytes(path, bytes);
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
  const auto path = dir / "snapshots.h5";
  Particles p;
  p.add(1, {0.001, 0.001, 0.001}, 0.001, 2500.0);
  append_snapshot(path, make_snapshot(p, 0.0, "pour", 0.0, 0));
  damage(path, [](std::vector<std::uint8_t>& bytes) {
    // The link message: version 1, flags 0x08 (a link type follows), type 64 (external), a name of 6.
    bytes.at(find(bytes, std::string("\x01\x08\x40\x06" "000000", 10)) + 1) = 0x7e;
  });
  const std::string m = file_error_of([&] { list_snapshots(path); });
  EXPECT_NE(m.find(path.string() + ": /snapshots: cannot read the group's links (damaged link messages?)"),
            std::string::npos)
      << m;
}

}  // namespace
