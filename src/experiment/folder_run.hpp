#pragma once
// The trapdoor experiment from a configuration to a run folder, saved and resumable: what
// `trapdem run` does and what a study runs for each case. Writes resolved.toml, run.log,
// snapshots.h5, trapdoor.csv, checkpoint.h5 and run.json (RunFolder names them; docs/output.md).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/line_sink.hpp"

namespace trapdem {

class RunRanks;  // run_ranks.hpp

struct FolderRunOptions {
  std::filesystem::path config_file;    // the configuration (TOML) to run; must be empty with resume_dir
  // Or the configuration as TOML text (from Python: a dict or a string), named `config_name` in
  // messages ("<dict>"); relative paths in it are taken from the working folder.
  std::string config_text;
  std::string config_name = "<configuration>";
  std::vector<std::string> overrides;   // "key.path=value", applied on top (with resume_dir: allowed_changes only)
  std::vector<std::string> allowed_changes;  // with resume_dir: keys that may differ from the run started
  std::filesystem::path out_dir;        // empty: ./trapdem-out/<name>
  std::filesystem::path resume_dir;     // non-empty: carry on the run in this folder from its checkpoint
  int threads = 0;                      // 0: the configuration's numerics.threads, else all cores
  bool quiet = false;                   // no progress lines on the terminal (run.log still has them)
  LineSink terminal;                    // where the terminal's lines go (default: stdout and stderr)
  double stop_after_seconds = 0.0;      // > 0: stop (with a checkpoint) after this much wall clock
  std::int64_t stop_at_step = 0;        // > 0: stop (with a checkpoint) at this engine step (tests)
  // The ranks the run spans (src/parallel's MpiRunRanks under mpirun; every rank calls
  // run_in_folder with the same options). Null: one process.
  RunRanks* ranks = nullptr;
};

// Runs (or resumes) the experiment into its folder. Returns true if it finished, false if it
// stopped on SIGINT/SIGTERM or a stop rule (its checkpoint written: resume it). Throws InputError,
// SimulationError or FileError; refuses a folder that already holds a run unless resuming.
// A resume is the run that was started: its configuration (the folder's resolved.toml with the
// overrides) is compared with the one stored in the checkpoint, and a key that differs is refused
// unless named in allowed_changes (then logged in run.log and recorded in resolved.toml). A folder
// without checkpoint.h5 but with resolved.toml (stopped before its first checkpoint) is started
// again from the beginning by a resume. On ranks the folder's files are rank 0's (run.log,
// resolved.toml, snapshots.h5, trapdoor.csv, checkpoint.h5, run.json) and an error on one rank is
// thrown on every rank (the lowest failing rank's).
bool run_in_folder(const FolderRunOptions& options);

}  // namespace trapdem
