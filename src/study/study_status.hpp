#pragma once
// Where a study stands, read from its folder alone (`trapdem study STUDY.toml --status`, issue 16):
// each run not started, running (its stage and percent from run.log), stopped with a checkpoint
// (resumable), finished, or failed (the last line of its log). Needs no Slurm: the runs' folders
// say it, wherever the runs ran.
#include <filesystem>
#include <string>
#include <vector>

#include "study/study_definition.hpp"

namespace trapdem {

enum class RunState { not_started, running, stopped, finished, failed };
std::string to_string(RunState state);

struct RunStatus {
  std::string title;                 // "smooth", "rf1 seed 2020"
  std::filesystem::path dir;
  RunState state = RunState::not_started;
  std::string stage;                 // the last progress line's stage (running, stopped), else empty
  double percent = -1.0;             // its percent of the stage; < 0: no progress line yet
  double seconds_since_log = -1.0;   // since run.log was last written (running, stopped)
  std::string last_line;             // run.log's last line (failed: the error)
};

// The state of the run in `dir`: not started (no run.log, no resolved.toml), finished (run.json
// says so), failed (run.log ends with "stopped by an error"), stopped (run.log ends with the stop
// line of a checkpointed stop: SIGTERM, SIGINT or a stop rule), else running. A run killed outright
// (SIGKILL, a node lost) reads as running until Slurm's own state says otherwise: its last log
// line's age is given for that reason.
RunStatus run_status(const std::filesystem::path& dir);

// Every run of the study at the scale in `out`, in the study's order.
std::vector<RunStatus> study_status(const StudyDefinition& study, const StudyScale& scale,
                                    const std::filesystem::path& out,
                                    const std::filesystem::path& preset_directory);

// The table `--status` prints: a line per run and a count per state.
std::string status_text(const std::vector<RunStatus>& runs);

}  // namespace trapdem
