// Issue 14: the LAMMPS readers refuse nan and inf (which std::from_chars reads as numbers) and
// name the line, instead of passing NaN positions on to the analysis.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "io/lammps_data.hpp"
#include "io/lammps_dump.hpp"

namespace trapdem {
namespace {

const std::string kDumpHeader =
    "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 0.2\n0 0.01\n0 0.4\n"
    "ITEM: ATOMS id x y z radius\n";

std::string dump_error(const std::string& atoms) {
  try {
    parse_dump(kDumpHeader + atoms, "run.dump");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(NonFiniteReaders, DumpRefusesNanAndInfNamingTheLine) {
  ASSERT_EQ(dump_error("1 0.1 0.005 0.05 0.001\n2 0.12 0.004 0.06 0.001\n"), "");
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity"}) {
    const std::string m = dump_error("1 0.1 0.005 0.05 0.001\n2 " + std::string(bad) + " 0.004 0.06 0.001\n");
    SCOPED_TRACE(m);
    EXPECT_NE(m.find("run.dump:11:"), std::string::npos);
    EXPECT_NE(m.find("not a finite number"), std::string::npos);
  }
  const std::string radius = dump_error("1 0.1 0.005 0.05 nan\n2 0.12 0.004 0.06 0.001\n");
  EXPECT_NE(radius.find("run.dump:10:"), std::string::npos) << radius;
  // A bound of the box that is not finite.
  std::string text = kDumpHeader;
  text.replace(text.find("0 0.4"), 5, "0 inf");
  try {
    parse_dump(text + "1 0.1 0.005 0.05 0.001\n2 0.12 0.004 0.06 0.001\n", "run.dump");
    ADD_FAILURE() << "accepted an infinite box bound";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.dump:8:"), std::string::npos) << e.what();
  }
}

TEST(NonFiniteReaders, DataFileRefusesNanNamingTheLine) {
  std::istringstream in(
      "LAMMPS data file\n\n2 atoms\n1 atom types\n\n0 0.1 xlo xhi\n0 0.0182 ylo yhi\n0 0.2 zlo zhi\n\n"
      "Atoms # sphere\n\n1 1 0.002 2500 0.01 nan 0.01\n2 1 0.002 2500 0.02 0.01 0.01\n");
  try {
    parse_lammps_data(in, "bad.data");
    ADD_FAILURE() << "accepted nan";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.data:12"), std::string::npos) << m;
    EXPECT_NE(m.find("expected a number"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace trapdem
