#pragma once
// A run folder: every file `trapdem run` and the commands after it write there (docs/output.md),
// named in one place, and the run's specimen read through the experiment's own configuration
// reader (ExperimentConfig::specimen_from), the one reader of resolved.toml.
#include <filesystem>
#include <string_view>

#include "experiment/analysis_folder.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

class RunFolder {
 public:
  explicit RunFolder(std::filesystem::path dir) : dir_(std::move(dir)) {}

  const std::filesystem::path& path() const { return dir_; }

  std::filesystem::path resolved_toml() const { return dir_ / "resolved.toml"; }  // the configuration as run
  std::filesystem::path run_log() const { return dir_ / "run.log"; }              // progress lines
  std::filesystem::path run_json() const { return dir_ / "run.json"; }            // the work so far (run_record.hpp)
  std::filesystem::path trapdoor_csv() const { return dir_ / "trapdoor.csv"; }    // ground reaction rows
  std::filesystem::path snapshots_h5() const { return dir_ / "snapshots.h5"; }
  std::filesystem::path checkpoint_h5() const { return dir_ / "checkpoint.h5"; }
  std::filesystem::path analysis_dir() const { return dir_ / "analysis"; }        // `trapdem analyze`
  AnalysisFolder analysis() const { return AnalysisFolder(analysis_dir()); }     // the files in it
  std::filesystem::path metrics_json() const { return analysis().metrics_json(); }
  std::filesystem::path camera_dir() const { return dir_ / "camera"; }            // `trapdem render`
  std::filesystem::path run_lock() const { return dir_ / "run.lock"; }            // held while a run writes (io/folder_lock.hpp)

  bool has_checkpoint() const { return std::filesystem::exists(checkpoint_h5()); }
  bool has_snapshots() const { return std::filesystem::exists(snapshots_h5()); }

  // The run's specimen (name, box, trapdoor, g level, fill height) from resolved.toml. Throws
  // InputError "<file>: not found; <needed_for>" if the folder has none, and the reader's errors
  // (file:line) for a bad value.
  ExperimentConfig specimen(std::string_view needed_for) const { return read_specimen(resolved_toml(), needed_for); }

  // The same from any file with [box] and [trapdoor] (a run made with another code).
  static ExperimentConfig read_specimen(const std::filesystem::path& toml, std::string_view needed_for);

 private:
  std::filesystem::path dir_;
};

}  // namespace trapdem
