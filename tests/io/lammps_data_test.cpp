#include "io/lammps_data.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "io_test_support.hpp"

using namespace trapdem;

namespace {

LammpsData parse(const std::string& text, const std::string& name = "test.data") {
  std::istringstream in(text);
  return parse_lammps_data(in, name);
}

// The message of the InputError that parsing `text` throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse(text, "bad.data");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kHeader =
    "LAMMPS data file via write_data\n"
    "\n"
    "2 atoms\n"
    "1 atom types\n"
    "\n"
    "0 0.1 xlo xhi\n"
    "0 0.0182 ylo yhi\n"
    "0 0.2 zlo zhi\n"
    "\n";

}  // namespace

TEST(LammpsData, ReadsHandWrittenFile) {
  const std::string text =
      "LAMMPS data file via write_data, version 2 Aug 2023, timestep = 45000, units = si\n"
      "\n"
      "3 atoms   # three spheres\n"
      "1 atom types\n"
      "\n"
      "0 0.1 xlo xhi\n"
      "-0.5e-3 1.82e-2 ylo yhi\n"
      "0 0.2 zlo zhi\n"
      "\n"
      "Atoms # sphere\n"
      "\n"
      "3 1 0.002 2500 0.01 0.002 0.003 0 0 0\n"
      "# a comment line inside the section\n"
      "1 1 0.002 2500 0.02 0.004 0.005 0 0 0\n"
      "7 2 0.004 1000 +0.03 0.006 1e-2 1 -1 0   # trailing comment\n"
      "\n"
      "Velocities\n"
      "\n"
      "1 0.1 0.2 0.3 1 2 3\n"
      "3 0 0 -0.5 0 0 0\n"
      "7 0 0 0 0 0 10\n";
  const LammpsData d = parse(text);
  EXPECT_EQ(d.title, "LAMMPS data file via write_data, version 2 Aug 2023, timestep = 45000, units = si");
  ASSERT_EQ(d.particles.size(), 3u);
  EXPECT_EQ(d.particles.id[0], 3);
  EXPECT_EQ(d.particles.id[1], 1);
  EXPECT_EQ(d.particles.id[2], 7);
  EXPECT_EQ(d.type[2], 2);
  EXPECT_DOUBLE_EQ(d.particles.radius[0], 0.001);
  EXPECT_DOUBLE_EQ(d.particles.radius[2], 0.002);
  EXPECT_DOUBLE_EQ(d.particles.density(0), 2500.0);
  EXPECT_DOUBLE_EQ(d.particles.density(2), 1000.0);
  EXPECT_NEAR(d.particles.mass[0], 2500.0 * 4.0 / 3.0 * std::numbers::pi * 1e-9, 1e-18);
  EXPECT_DOUBLE_EQ(d.particles.position[2].x, 0.03);
  EXPECT_DOUBLE_EQ(d.particles.position[2].z, 0.01);
  EXPECT_EQ(d.particles.image[2].x, 1);
  EXPECT_EQ(d.particles.image[2].y, -1);
  EXPECT_DOUBLE_EQ(d.box_lower.y, -0.5e-3);
  EXPECT_DOUBLE_EQ(d.box_upper.x, 0.1);
  EXPECT_DOUBLE_EQ(d.box_upper.y, 0.0182);
  EXPECT_DOUBLE_EQ(d.box_upper.z, 0.2);
  EXPECT_TRUE(d.has_velocities);
  EXPECT_DOUBLE_EQ(d.particles.velocity[1].y, 0.2);   // id 1
  EXPECT_DOUBLE_EQ(d.particles.angular_velocity[1].z, 3.0);
  EXPECT_DOUBLE_EQ(d.particles.velocity[0].z, -0.5);  // id 3
  EXPECT_DOUBLE_EQ(d.particles.angular_velocity[2].z, 10.0);
}

TEST(LammpsData, AcceptsLiggghtsStyleWithoutVelocitiesOrImages) {
  // LIGGGHTS writes "Atoms" without the style comment; image flags are optional.
  const LammpsData d = parse(std::string(kHeader) +
                             "Masses\n\n1 1.0\n\n"
                             "Atoms\n\n1 1 0.002 2500 0.01 0.01 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n");
  ASSERT_EQ(d.particles.size(), 2u);
  EXPECT_FALSE(d.has_velocities);
  EXPECT_EQ(d.particles.velocity[1], Vec3{});
  EXPECT_EQ(d.particles.image[0].x, 0);
}

TEST(LammpsData, RoundTripIsExact) {
  Particles p;
  p.add(5, {0.012345678901234567, 1.0 / 3.0, 2e-3}, 0.001, 2500.0, {0.1, -0.2, 1.0 / 7.0}, {3.0, 0.0, -1e-9});
  p.add(2, {0.05, 0.009, 0.19}, 0.0015, 1234.5);
  p.add(9, {0.099, 1e-4, 0.001}, 0.00123456789, 7800.0, {}, {0.0, 11.0, 0.0});
  p.image[1] = {1, 0, -2};
  const Vec3 lo{0, 0, 0}, hi{0.1, 0.0182, 0.2};
  const io_testing::ScratchDir dir("trapdem-lammps-data");
  const auto path = dir / "round_trip.data";
  LammpsWriteOptions opt;
  opt.type = {1, 2, 1};
  write_lammps_data(path.string(), p, lo, hi, opt);
  const LammpsData d = read_lammps_data(path.string());
  ASSERT_EQ(d.particles.size(), p.size());
  EXPECT_EQ(d.box_lower, lo);
  EXPECT_EQ(d.box_upper, hi);
  EXPECT_TRUE(d.has_velocities);
  EXPECT_EQ(d.type, opt.type);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(d.particles.id[i], p.id[i]);
    EXPECT_EQ(d.particles.radius[i], p.radius[i]);
    EXPECT_DOUBLE_EQ(d.particles.mass[i], p.mass[i]);
    EXPECT_EQ(d.particles.position[i], p.position[i]);
    EXPECT_EQ(d.particles.velocity[i], p.velocity[i]);
    EXPECT_EQ(d.particles.angular_velocity[i], p.angular_velocity[i]);
    EXPECT_EQ(d.particles.image[i].x, p.image[i].x);
    EXPECT_EQ(d.particles.image[i].z, p.image[i].z);
  }
}

TEST(LammpsData, MissingFileNamesIt) {
  try {
    read_lammps_data("/nonexistent/dir/pack.data");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/pack.data"), std::string::npos);
  }
}

TEST(LammpsData, MissingAtomsSection) {
  const std::string e = error_of(std::string(kHeader) + "Velocities\n\n1 0 0 0 0 0 0\n2 0 0 0 0 0 0\n");
  EXPECT_NE(e.find("bad.data:"), std::string::npos) << e;
  EXPECT_NE(e.find("no Atoms section"), std::string::npos) << e;
}

TEST(LammpsData, MissingAtomCountOrBox) {
  EXPECT_NE(error_of("title\n\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n\nAtoms\n\n1 1 0.002 2500 0 0 0\n")
                .find("'N atoms'"),
            std::string::npos);
  const std::string e = error_of("title\n1 atoms\n0 1 xlo xhi\n0 1 ylo yhi\nAtoms\n\n1 1 0.002 2500 0 0 0\n");
  EXPECT_NE(e.find("zlo zhi"), std::string::npos) << e;
}

TEST(LammpsData, WrongColumnCount) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # sphere\n\n1 1 0.002 2500 0.01 0.01 0.01\n2 1 0.002 0.02 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:13:"), std::string::npos) << e;
  EXPECT_NE(e.find("6 columns"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 7 or 10"), std::string::npos) << e;
}

TEST(LammpsData, NonNumber) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # sphere\n\n1 1 0.002 2500 0.01 abc 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:12:"), std::string::npos) << e;
  EXPECT_NE(e.find("'abc'"), std::string::npos) << e;
  EXPECT_NE(e.find("(y)"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a number"), std::string::npos) << e;
}

TEST(LammpsData, NonIntegerId) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # sphere\n\n1.5 1 0.002 2500 0.01 0.01 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:12:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected an integer"), std::string::npos) << e;
}

TEST(LammpsData, CountMismatchTooFew) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # sphere\n\n1 1 0.002 2500 0.01 0.01 0.01\n\nVelocities\n\n1 0 0 0 0 0 0\n");
  EXPECT_NE(e.find("bad.data:10:"), std::string::npos) << e;  // the Atoms line
  EXPECT_NE(e.find("has 1 lines; expected 2"), std::string::npos) << e;
}

TEST(LammpsData, CountMismatchTooMany) {
  const std::string e = error_of(std::string(kHeader) +
                                 "Atoms # sphere\n\n1 1 0.002 2500 0.01 0.01 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n"
                                 "3 1 0.002 2500 0.03 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:14:"), std::string::npos) << e;  // the first extra line
  EXPECT_NE(e.find("has 3 lines; expected 2"), std::string::npos) << e;
}

TEST(LammpsData, VelocityCountMismatch) {
  const std::string e = error_of(std::string(kHeader) +
                                 "Atoms # sphere\n\n1 1 0.002 2500 0.01 0.01 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n"
                                 "\nVelocities\n\n1 0 0 0 0 0 0\n");
  EXPECT_NE(e.find("Velocities section has 1 lines; expected 2"), std::string::npos) << e;
}

TEST(LammpsData, NegativeDiameter) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # sphere\n\n1 1 0.002 2500 0.01 0.01 0.01\n2 1 -0.002 2500 0.02 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:13:"), std::string::npos) << e;
  EXPECT_NE(e.find("diameter -0.002"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a positive diameter"), std::string::npos) << e;
}

TEST(LammpsData, OtherAtomStyleIsRejected) {
  const std::string e = error_of(std::string(kHeader) + "Atoms # atomic\n\n1 1 0.01 0.01 0.01\n2 1 0.02 0.01 0.01\n");
  EXPECT_NE(e.find("bad.data:10:"), std::string::npos) << e;
  EXPECT_NE(e.find("atom_style 'atomic'"), std::string::npos) << e;
}

TEST(LammpsData, DuplicateAndUnknownIds) {
  EXPECT_NE(error_of(std::string(kHeader) + "Atoms\n\n1 1 0.002 2500 0 0 0\n1 1 0.002 2500 0.01 0 0\n").find("appears twice"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kHeader) +
                     "Atoms\n\n1 1 0.002 2500 0 0 0\n2 1 0.002 2500 0.01 0 0\n\nVelocities\n\n1 0 0 0 0 0 0\n5 0 0 0 0 0 0\n")
                .find("bad.data:18: velocity of atom id 5"),
            std::string::npos);
}
