// LAMMPS/LIGGGHTS text dumps: columns in any order, scaled coordinates, diameter instead of
// radius; every malformed input names the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/lammps_dump.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

const char* header = "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 0.2\n0 0.01\n0 0.4\n";

// The message of the InputError that parsing `text` throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse_dump(text, "run.dump");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DumpReader, ReadsColumnsInAnyOrder) {
  const Snapshot s = parse_dump(std::string(header) +
                                    "ITEM: ATOMS type radius z id y x vx\n1 0.001 0.05 7 0.005 0.1 0\n"
                                    "1 0.0015 0.06 3 0.004 0.12 0\n",
                                "run.dump");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.step, 1000);
  EXPECT_EQ(s.id[0], 7);
  EXPECT_EQ(s.id[1], 3);
  EXPECT_DOUBLE_EQ(s.position[1].x, 0.12);
  EXPECT_DOUBLE_EQ(s.position[1].y, 0.004);
  EXPECT_DOUBLE_EQ(s.position[1].z, 0.06);
  EXPECT_DOUBLE_EQ(s.radius[1], 0.0015);
}

TEST(DumpReader, ScaledCoordinatesAndDiameter) {
  const Snapshot s = parse_dump(std::string(header) + "ITEM: ATOMS id xs ys zs diameter\n1 0.5 0.5 0.25 0.002\n"
                                                      "2 0 1 1 0.004\n",
                                "run.dump");
  EXPECT_DOUBLE_EQ(s.position[0].x, 0.1);
  EXPECT_DOUBLE_EQ(s.position[0].z, 0.1);
  EXPECT_DOUBLE_EQ(s.position[1].y, 0.01);
  EXPECT_DOUBLE_EQ(s.radius[0], 0.001);
  EXPECT_DOUBLE_EQ(s.radius[1], 0.002);
}

TEST(DumpReader, BadInputNamesFileAndLine) {
  const std::string atoms = "ITEM: ATOMS id x y z radius\n";
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\n2 0.1 oops 0.05 0.001\n"),
            "run.dump:11: coordinate: 'oops' is not a number");
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\n2 0.1 0.005\n"),
            "run.dump:11: expected 5 columns, found 3");
  EXPECT_EQ(error_of(std::string(header) + "ITEM: ATOMS id x y z\n1 0.1 0.005 0.05\n2 0.1 0.005 0.05\n"),
            "run.dump:9: the ATOMS columns lack radius (dump with: id x y z radius)");
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\n1 0.1 0.005 0.06 0.001\n"),
            "run.dump:11: id 1 appears twice");
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\nITEM: TIMESTEP\n2000\n"),
            "run.dump:11: expected 2 atom lines, found 1");
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\n2 0.1 0.005 0.05 -1\n"),
            "run.dump:11: the radius of atom 2 must be positive");
  EXPECT_EQ(error_of(std::string(header) + atoms + "1 0.1 0.005 0.05 0.001\n2 0.1 0.005 0.05 0.001\nITEM: TIMESTEP\n5\n"),
            "run.dump:12: a second TIMESTEP: give one dump file per snapshot");
  EXPECT_EQ(error_of("ITEM: TIMESTEP\nabc\n"), "run.dump:2: timestep: 'abc' is not a number");
  EXPECT_EQ(error_of("hello\n"), "run.dump:1: expected an 'ITEM:' line, found 'hello'");
  EXPECT_EQ(error_of("ITEM: TIMESTEP\n1\n"), "run.dump: no ITEM: ATOMS section (not a LAMMPS/LIGGGHTS text dump?)");
  // Not there: a wrong name given, an input error (exit 2); there but unreadable: a file error.
  EXPECT_THROW(read_dump_file("/nonexistent/run.dump"), InputError);
}
