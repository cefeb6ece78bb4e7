// The HDF5 readers of a run folder: snapshots.h5 (list_snapshots, read_snapshots) and
// checkpoint.h5 (read_checkpoint), given a damaged or hostile file. The readers take a path.
// HDF5 (Debian's libhdf5) is not instrumented: coverage guides only our readers.
#include "fuzz_target.hpp"
#include "io/checkpoint.hpp"
#include "io/snapshot.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzzing::input_file(fuzzing::as_text(data, size), "input.h5");
  fuzzing::expecting_clear_errors([&] {
    for (const SnapshotInfo& info : list_snapshots(file)) read_snapshot(file, info.name);
  });
  fuzzing::expecting_clear_errors([&] { read_checkpoint(file); });
  return 0;
}
