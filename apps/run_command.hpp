#pragma once
// `trapdem run` and `trapdem presets`: the trapdoor experiment from configuration to saved,
// resumable results.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem::app {

struct RunOptions {
  std::string config_file;              // a TOML file, or empty
  std::string preset;                   // a preset name, or empty
  std::string out_dir;                  // empty: ./trapdem-out/<name>
  std::vector<std::string> overrides;   // "key.path=value"
  std::string resume_dir;               // continue the run in this folder from its checkpoint
  std::vector<std::string> allowed_changes;  // --allow-change KEY: with --resume, KEY may differ (logged)
  int threads = 0;                      // 0: the configuration's numerics.threads, else all cores
  bool quiet = false;                   // no progress lines on the terminal (run.log still has them)
  double stop_after_seconds = 0.0;      // > 0: stop (with a checkpoint) after this much wall clock
  std::int64_t stop_at_step = 0;        // > 0: stop (with a checkpoint) at this engine step (tests)
};

// Returns the process exit code; throws InputError / SimulationError / FileError on failure.
int run_experiment(const RunOptions& options);

std::filesystem::path preset_directory();
std::filesystem::path preset_path(const std::string& name);
int list_presets();

}  // namespace trapdem::app
