// The HDF5 readers of a run folder: snapshots.h5 (list_snapshots, read_snapshots) and
// checkpoint.h5 (read_checkpoint), given a damaged or hostile file. The readers take a path.
// HDF5 (Debian's libhdf5) is not instrumented: coverage guides only our readers.
// The readers open a file only after a child process has read it through libhdf5 (io/hdf5_probe):
// a crash or hang of libhdf5 there is the readers' FileError, not a finding; a crash here, in the
// reading process, is. The child's wall-clock limit stays below libFuzzer's -timeout (10 s in
// run-fuzz.sh). The input file is rewritten in place for each input: the probe forgets it then,
// and within one input remembers it however recent (each reader opens it again).
#include "fuzz_target.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5_probe.hpp"
#include "io/snapshot.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool limited = [] {
    set_hdf5_probe_limits({std::chrono::milliseconds(4000), std::chrono::seconds(3), std::size_t(1) << 30,
                           std::chrono::milliseconds(0)});
    return true;
  }();
  (void)limited;
  forget_probed_hdf5_files();
  const auto file = fuzzing::input_file(fuzzing::as_text(data, size), "input.h5");
  fuzzing::expecting_clear_errors([&] {
    for (const SnapshotInfo& info : list_snapshots(file)) read_snapshot(file, info.name);
  });
  fuzzing::expecting_clear_errors([&] { read_checkpoint(file); });
  return 0;
}
