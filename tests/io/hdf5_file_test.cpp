// The HDF5 wrapper: every supported dataset and attribute kind round-trips exactly, and failures
// name the file and the object.
#include "io/hdf5_file.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <thread>

#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

TEST(Hdf5File, DatasetsAndAttributesRoundTrip) {
  ScratchDir dir;
  const auto path = dir / "data.h5";
  const std::vector<double> doubles{0.1, -1.0 / 3.0, std::numeric_limits<double>::denorm_min(), 1e308};
  const std::vector<std::int64_t> ints{-1, 0, std::numeric_limits<std::int64_t>::max()};
  const std::vector<std::uint32_t> u32{0u, 7u, 0xffffffffu};
  const std::vector<std::uint8_t> u8{0, 1, 255};
  const std::vector<Vec3> vecs{{1, 2, 3}, {-0.1, 0.2, -0.3}};
  const std::vector<Int3> images{{1, -2, 3}, {0, 0, -7}};
  const std::vector<std::string> names{"floor", "trapdoor", ""};
  {
    Hdf5File f = Hdf5File::create(path);
    f.set_string_attribute("format", "test");
    f.set_double_attribute("time", 0.125);
    f.set_int_attribute("step", 42);
    const Hdf5Group g = f.create_group("a").create_group("b");
    g.write_doubles("doubles", doubles, "m");
    g.write_int64s("ints", ints);
    g.write_uint32s("u32", u32);
    g.write_uint8s("u8", u8);
    g.write_vec3s("vecs", vecs, "m/s");
    g.write_int3s("images", images);
    g.write_strings("names", names);
    g.write_doubles("empty", std::vector<double>{});
    g.write_vec3s("empty3", std::vector<Vec3>{});
    f.close();
  }
  const Hdf5File f = Hdf5File::open_read(path);
  EXPECT_EQ(f.string_attribute("format"), "test");
  EXPECT_EQ(f.double_attribute("time"), 0.125);
  EXPECT_EQ(f.int_attribute("step"), 42);
  EXPECT_EQ(f.attribute_names(), (std::vector<std::string>{"format", "step", "time"}));
  EXPECT_TRUE(f.has("a"));
  const Hdf5Group g = f.group("a").group("b");
  EXPECT_EQ(g.path(), "/a/b");
  EXPECT_EQ(g.read_doubles("doubles"), doubles);
  EXPECT_EQ(g.read_int64s("ints"), ints);
  EXPECT_EQ(g.read_uint32s("u32"), u32);
  EXPECT_EQ(g.read_uint8s("u8"), u8);
  const std::vector<Vec3> v = g.read_vec3s("vecs");
  ASSERT_EQ(v.size(), vecs.size());
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], vecs[i]);
  const std::vector<Int3> im = g.read_int3s("images");
  ASSERT_EQ(im.size(), 2u);
  EXPECT_EQ(im[0].y, -2);
  EXPECT_EQ(im[1].z, -7);
  EXPECT_EQ(g.read_strings("names"), names);
  EXPECT_TRUE(g.read_doubles("empty").empty());
  EXPECT_TRUE(g.read_vec3s("empty3").empty());
  EXPECT_EQ(g.dataset_length("vecs"), 2u);
  EXPECT_EQ(g.children(), (std::vector<std::string>{"doubles", "empty", "empty3", "images", "ints", "names", "u32",
                                                    "u8", "vecs"}));
  // The stored type is converted on reading (as for files written by other tools).
  EXPECT_EQ(g.read_doubles("ints")[0], -1.0);
}

// Two writes of the same content are the same bytes: no object carries its modification time (HDF5
// stamps groups and datasets by default, to the second), so a re-analysis that changes nothing
// leaves its files, and the published copies of them, unchanged.
TEST(Hdf5File, TheSameContentWrittenAtTwoTimesIsTheSameBytes) {
  ScratchDir dir;
  auto write = [](const std::filesystem::path& path) {
    Hdf5File f = Hdf5File::create(path);
    f.set_string_attribute("format", "test");
    const Hdf5Group g = f.create_group("fields");
    g.write_doubles("time", std::vector<double>{0.0, 0.5}, "s");
    g.write_float_stack("settlement", FloatStack{2, 2, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}}, "m");
    f.close();
  };
  write(dir / "first.h5");
  // Past the next whole second: HDF5's time stamps have a resolution of one second.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write(dir / "second.h5");
  auto bytes = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string first = bytes(dir / "first.h5"), second = bytes(dir / "second.h5");
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "the two files differ (" << first.size() << " and " << second.size() << " bytes)";
}

TEST(Hdf5File, ErrorsNameTheFileAndTheObject) {
  ScratchDir dir;
  const auto path = dir / "data.h5";
  {
    Hdf5File f = Hdf5File::create(path);
    f.create_group("g").write_vec3s("position", std::vector<Vec3>{{1, 2, 3}});
    f.close();
  }
  const Hdf5File f = Hdf5File::open_read(path);
  const Hdf5Group g = f.group("g");
  std::string m = file_error_of([&] { g.read_doubles("velocity"); });
  EXPECT_NE(m.find(path.string() + ": /g/velocity: no such dataset"), std::string::npos) << m;
  m = file_error_of([&] { g.read_doubles("position"); });
  EXPECT_NE(m.find("/g/position: expected a 1-D dataset, found a dataset of rank 2 (1 x 3)"), std::string::npos) << m;
  m = file_error_of([&] { f.group("h"); });
  EXPECT_NE(m.find("/h: no such group"), std::string::npos) << m;
  m = file_error_of([&] { f.double_attribute("time"); });
  EXPECT_NE(m.find("no attribute 'time'"), std::string::npos) << m;
  m = file_error_of([&] { g.write_doubles("x", std::vector<double>{1.0}); });  // read-only file
  EXPECT_NE(m.find(path.string() + ": /g/x"), std::string::npos) << m;

  const auto text = dir / "not.h5";
  std::ofstream(text) << "this is not HDF5\n";
  m = file_error_of([&] { Hdf5File::open_read(text); });
  EXPECT_NE(m.find(text.string()), std::string::npos) << m;
  m = file_error_of([&] { Hdf5File::open_read(dir / "missing.h5"); });
  EXPECT_NE(m.find("missing.h5: no such file"), std::string::npos) << m;
  m = file_error_of([&] { Hdf5File::create(dir / "no" / "such" / "folder.h5"); });
  EXPECT_NE(m.find("folder.h5: cannot create"), std::string::npos) << m;
}
