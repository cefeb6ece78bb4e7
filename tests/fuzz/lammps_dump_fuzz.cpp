// A LAMMPS / LIGGGHTS text dump, as `trapdem analyze` reads the snapshots of a run made elsewhere.
#include "fuzz_target.hpp"
#include "io/lammps_dump.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(fuzzing::as_text(data, size));
  fuzzing::expecting_clear_errors([&] { parse_dump(text, "fuzz.dump"); });
  return 0;
}
