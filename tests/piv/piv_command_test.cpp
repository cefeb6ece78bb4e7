// The commands of issue 5 as a user runs them (apps/piv_command.hpp): `trapdem synth` writes the
// images and truth.csv; `trapdem piv` on them writes displacements.csv (exact header, values
// matching the truth), piv.h5 with the datasets of docs/piv.md and the figures; bad input is an
// InputError with a clear message, which the binary turns into exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/errors.hpp"
#include "piv_test_support.hpp"
#include "io/hdf5_file.hpp"
#include "piv_command.hpp"
#include "../io/io_test_support.hpp"

namespace trapdem {
namespace {

using test::expect_input_error;

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> v;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, ',')) v.push_back(item);
  return v;
}

// truth.csv as maps column -> value, one per image.
std::vector<std::map<std::string, std::string>> read_truth(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto v = split(line);
    EXPECT_EQ(v.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < std::min(v.size(), header.size()); ++i) row[header[i]] = v[i];
    rows.push_back(row);
  }
  return rows;
}

// Per process: ctest runs the tests of one fixture as parallel processes, which would otherwise
// remove each other's folders (a fixture's tests share a name). Removed at the process's exit.
fs::path fresh_dir(const std::string& name) {
  static const io_testing::ScratchDir root("trapdem-piv-command");
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Small rigid-shift sequence (3 images, 160 x 128 px, last shift (1.5, 0.9) px, 0.5 grey levels noise).
fs::path synth_rigid(const std::string& name) {
  app::SynthOptions o;
  o.field = "rigid";
  o.out = (fresh_dir(name) / "images").string();
  o.size = "160x128";
  o.images = 3;
  o.noise = 0.5;
  o.magnitude = 1.5;
  o.seed = 7;
  EXPECT_EQ(app::run_synth_command(o), 0);
  return o.out;
}

TEST(PivCommand, SynthWritesImagesAndTruth) {
  const fs::path dir = synth_rigid("synth");
  for (const char* name : {"image_001.png", "image_002.png", "image_003.png", "truth.csv"}) {
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  }
  const cv::Mat first = cv::imread((dir / "image_001.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first.cols, 160);
  EXPECT_EQ(first.rows, 128);
  EXPECT_EQ(first.type(), CV_8UC1);
  const auto truth = read_truth(dir / "truth.csv");
  ASSERT_EQ(truth.size(), 3u);
  EXPECT_EQ(truth[0].at("file"), "image_001.png");
  EXPECT_DOUBLE_EQ(std::stod(truth[0].at("u_px")), 0.0);
  EXPECT_DOUBLE_EQ(std::stod(truth[1].at("u_px")), 0.75);
  EXPECT_DOUBLE_EQ(std::stod(truth[2].at("u_px")), 1.5);
  EXPECT_DOUBLE_EQ(std::stod(truth[2].at("v_px")), 0.9);
  EXPECT_EQ(truth[2].at("field"), "rigid");
}

TEST(PivCommand, PivOnSyntheticRigidShiftWritesCsvH5AndFigures) {
  const fs::path images = synth_rigid("piv");
  const auto truth = read_truth(images / "truth.csv");
  ASSERT_EQ(truth.size(), 3u);
  app::PivOptions o;
  for (int k = 1; k <= 3; ++k) o.images.push_back((images / ("image_00" + std::to_string(k) + ".png")).string());
  o.out = (images.parent_path() / "out").string();
  o.threads = 2;
  o.quiet = true;
  ASSERT_EQ(app::run_piv_command(o), 0);
  const fs::path out = o.out;

  // displacements.csv: exact header, every subset of every image, values within 0.02 px.
  std::ifstream csv(out / "displacements.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "image,x_px,y_px,u_px,v_px,zncc,valid");
  std::map<int, int> rows_per_image, valid_per_image, inside_per_image;
  double worst = 0.0;
  while (std::getline(csv, line)) {
    const auto v = split(line);
    ASSERT_EQ(v.size(), 7u) << line;
    const int image = std::stoi(v[0]);
    ASSERT_GE(image, 1);
    ASSERT_LE(image, 3);
    ++rows_per_image[image];
    // Inside: the displaced subset's pixels stay within the image's pixel centres [0, 159] x [0, 127].
    const double x = std::stod(v[1]) + std::stod(truth[image - 1].at("u_px"));
    const double y = std::stod(v[2]) + std::stod(truth[image - 1].at("v_px"));
    const bool inside = x - 15.5 >= 0.0 && x + 15.5 <= 159.0 && y - 15.5 >= 0.0 && y + 15.5 <= 127.0;
    inside_per_image[image] += inside;
    if (v[6] != "1") {
      EXPECT_FALSE(inside) << "a subset inside the image is not valid: " << line;
      continue;
    }
    ++valid_per_image[image];
    const double du = std::stod(v[3]) - std::stod(truth[image - 1].at("u_px"));
    const double dv = std::stod(v[4]) - std::stod(truth[image - 1].at("v_px"));
    worst = std::max({worst, std::abs(du), std::abs(dv)});
    EXPECT_GT(std::stod(v[5]), 0.9) << line;
  }
  // 160 x 128, 32 px subsets every 16 px from the corner: 9 x 7 subsets; every subset still inside
  // the image is valid (image 1: all 63; images 2 and 3: the right column and bottom row leave it).
  for (int k = 1; k <= 3; ++k) {
    EXPECT_EQ(rows_per_image[k], 63) << "image " << k;
    EXPECT_EQ(valid_per_image[k], inside_per_image[k]) << "image " << k;
  }
  EXPECT_EQ(valid_per_image[1], 63);
  EXPECT_EQ(valid_per_image[3], 48);
  std::printf("[ measured ] worst |PIV - truth| over u, v of the valid subsets: %.4f px (tolerance 0.02)\n", worst);
  EXPECT_LT(worst, 0.02);

  // piv.h5: the layout of docs/piv.md.
  const Hdf5File h5 = Hdf5File::open_read(out / "piv.h5");
  const Hdf5Group grid = h5.group("grid");
  EXPECT_EQ(grid.dataset_length("x_px"), 63u);
  EXPECT_EQ(grid.dataset_length("y_px"), 63u);
  EXPECT_EQ(grid.int_attribute("subset_size"), 32);
  EXPECT_EQ(grid.int_attribute("step"), 16);
  EXPECT_EQ(grid.int_attribute("columns"), 9);
  EXPECT_EQ(grid.int_attribute("rows"), 7);
  const Hdf5Group imgs = h5.group("images");
  EXPECT_EQ(imgs.children(), (std::vector<std::string>{"000001", "000002", "000003"}));
  for (const auto& name : imgs.children()) {
    const Hdf5Group g = imgs.group(name);
    for (const char* d : {"u_px", "v_px", "zncc"}) EXPECT_EQ(g.read_doubles(d).size(), 63u) << name << "/" << d;
    EXPECT_EQ(g.read_uint8s("status").size(), 63u);
    const auto valid = g.read_uint8s("valid");
    ASSERT_EQ(valid.size(), 63u);
    std::int64_t count = 0;
    for (auto x : valid) count += x;
    EXPECT_TRUE(g.has_attribute("name"));
    EXPECT_TRUE(g.has_attribute("reference_image"));
    EXPECT_TRUE(g.has_attribute("seconds"));
    EXPECT_EQ(g.int_attribute("valid_count"), count);
    EXPECT_EQ(count, valid_per_image[std::stoi(name)]) << name;
    if (name != "000001") {
      for (const char* s : {"strain_total", "strain_incremental"}) {
        ASSERT_TRUE(g.has(s)) << name << "/" << s;
        const Hdf5Group sg = g.group(s);
        for (const char* d : {"node_subset", "node_x", "node_z", "node_dx", "node_dz", "triangles", "max_shear",
                              "volumetric"}) {
          EXPECT_TRUE(sg.has(d)) << name << "/" << s << "/" << d;
        }
        const auto shear = sg.read_doubles("max_shear");
        EXPECT_GT(shear.size(), 0u);
        EXPECT_EQ(sg.read_uint32s("triangles").size(), 3 * shear.size());
        for (double x : shear) EXPECT_LT(std::abs(x), 2e-3) << "rigid shift: no shear strain";
      }
    }
  }
  const auto v3 = imgs.group("000003").read_doubles("v_px");
  const auto valid3 = imgs.group("000003").read_uint8s("valid");
  for (std::size_t i = 0; i < v3.size(); ++i) {
    if (valid3[i]) {
      EXPECT_NEAR(v3[i], 0.9, 0.02);
    }
  }

  // Figures: written, readable PNGs.
  for (const char* name : {"shear_strain.png", "shear_strain_incremental.png", "vertical_displacement.png",
                           "vectors.png", "correlation_quality.png"}) {
    const cv::Mat m = cv::imread((out / name).string());
    EXPECT_FALSE(m.empty()) << name;
  }
}

TEST(PivCommand, WithScaleTheH5HasModelCoordinates) {
  const fs::path images = synth_rigid("scale");
  app::PivOptions o;
  o.images = {(images / "image_001.png").string(), (images / "image_003.png").string()};
  o.out = (images.parent_path() / "out").string();
  o.scale = 0.1;
  o.threads = 2;
  o.quiet = true;
  o.no_figures = true;
  ASSERT_EQ(app::run_piv_command(o), 0);
  EXPECT_FALSE(fs::exists(fs::path(o.out) / "shear_strain.png"));
  const Hdf5File h5 = Hdf5File::open_read(fs::path(o.out) / "piv.h5");
  EXPECT_EQ(h5.group("model").read_doubles("pixel_to_model").size(), 9u);
  const Hdf5Group g = h5.group("images").group("000002");
  const auto u = g.read_doubles("u_model");
  const auto w = g.read_doubles("w_model");
  const auto valid = g.read_uint8s("valid");
  ASSERT_EQ(u.size(), 63u);
  ASSERT_EQ(valid.size(), 63u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!valid[i]) continue;
    EXPECT_NEAR(u[i], 0.15, 0.002);
    EXPECT_NEAR(w[i], -0.09, 0.002);  // z up: the image's +0.9 px (down) is -0.09 mm
  }
}

class PivCommandBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    images_ = synth_rigid("bad");
    options_.images = {(images_ / "image_001.png").string(), (images_ / "image_002.png").string()};
    options_.out = (images_.parent_path() / "out").string();
    options_.quiet = true;
    options_.no_figures = true;
  }
  fs::path images_;
  app::PivOptions options_;
};

TEST_F(PivCommandBadInput, ImagesOfDifferentSizes) {
  const cv::Mat a = cv::imread(options_.images[1], cv::IMREAD_UNCHANGED);
  cv::Mat b;
  cv::resize(a, b, cv::Size(150, 128));
  const fs::path other = images_ / "smaller.png";
  cv::imwrite(other.string(), b);
  options_.images[1] = other.string();
  expect_input_error([&] { app::run_piv_command(options_); }, "same size");
  EXPECT_FALSE(fs::exists(fs::path(options_.out) / "displacements.csv"));
}

TEST_F(PivCommandBadInput, UnreadableFile) {
  const fs::path text = images_ / "not_an_image.png";
  std::ofstream(text) << "text, not a PNG\n";
  options_.images[1] = text.string();
  expect_input_error([&] { app::run_piv_command(options_); }, "not_an_image.png");
  options_.images[1] = (images_ / "missing.png").string();
  expect_input_error([&] { app::run_piv_command(options_); }, "no such file");
}

TEST_F(PivCommandBadInput, EmptyRegionOfInterest) {
  options_.roi = "40,10,40,70";
  expect_input_error([&] { app::run_piv_command(options_); }, "empty");
  options_.roi = "50,60,20,10";
  expect_input_error([&] { app::run_piv_command(options_); }, "empty");
  options_.roi = "0,0,10";
  expect_input_error([&] { app::run_piv_command(options_); }, "--roi");
}

TEST_F(PivCommandBadInput, SubsetLargerThanTheImage) {
  options_.subset = 200;
  expect_input_error([&] { app::run_piv_command(options_); }, "larger than the image");
}

TEST_F(PivCommandBadInput, OneImageOrNoOutputFolder) {
  options_.images.resize(1);
  expect_input_error([&] { app::run_piv_command(options_); }, "at least two images");
  app::SynthOptions s;
  s.field = "spiral";
  s.out = (images_.parent_path() / "spiral").string();
  expect_input_error([&] { app::run_synth_command(s); }, "--field");
}

// The binary maps InputError to exit code 2 with a one-line message (apps/main.cpp). The build
// makes the trapdem command before this test program.
TEST_F(PivCommandBadInput, BinaryExitsWithCode2) {
  const fs::path binary = TRAPDEM_EXECUTABLE;
  ASSERT_TRUE(fs::is_regular_file(binary)) << binary << " not built";
  const fs::path err = images_.parent_path() / "stderr.txt";
  const std::string cmd = "'" + binary.string() + "' piv '" + options_.images[0] + "' '" + options_.images[1] +
                          "' --out '" + options_.out + "' --roi 40,10,40,70 --quiet --no-figures 2> '" +
                          err.string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream in(err);
  std::string message;
  std::getline(in, message);
  EXPECT_NE(message.find("input error"), std::string::npos) << message;
  EXPECT_NE(message.find("--roi"), std::string::npos) << message;
}

}  // namespace
}  // namespace trapdem
