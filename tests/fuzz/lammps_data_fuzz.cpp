// A LAMMPS data file (atom_style sphere) as `trapdem run` reads a packing from another code.
#include <sstream>

#include "fuzz_target.hpp"
#include "io/lammps_data.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in{std::string(fuzzing::as_text(data, size))};
  fuzzing::expecting_clear_errors([&] { parse_lammps_data(in, "fuzz.data"); });
  return 0;
}
