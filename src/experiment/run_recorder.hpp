#pragma once
// The observer that writes a run folder's files as the experiment reports its events: run.log
// (and the terminal unless quiet), snapshots.h5, trapdoor.csv and checkpoint.h5 (every stage end
// and every output.checkpoint_interval of wall clock); it asks the experiment to stop on a
// signal, after a wall-clock budget or at a given step (tests). On ranks (RunRanks) the files are
// rank 0's, written from the particles gathered there, and the decisions taken on a clock
// (checkpoint, stop) are agreed on, so every rank checkpoints and stops at the same step.
#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "experiment/run_folder.hpp"
#include "experiment/run_log.hpp"
#include "experiment/run_ranks.hpp"
#include "experiment/run_record.hpp"
#include "experiment/trapdoor_experiment.hpp"

namespace trapdem {

struct RunStopRules {
  const std::atomic<int>* signal = nullptr;  // non-zero: stop (SIGINT/SIGTERM seen)
  double after_seconds = 0.0;                // > 0: stop after this much wall clock
  std::int64_t at_step = 0;                  // > 0: stop at this engine step
};

class RunRecorder : public ExperimentObserver {
 public:
  // Writes the run's lines to `log` (the folder's run.log, opened before the run by the caller; on
  // ranks, rank 0's: null on the others).
  RunRecorder(TrapdoorExperiment& experiment, RunFolder folder, RunLog* log, RunStopRules stop,
              RunRanks* ranks = nullptr);

  // A line for run.log and, unless quiet, the terminal.
  void say(const std::string& line) {
    if (log_) log_->say(line);
  }

  // The run's resolved configuration (run_identity.hpp: resolved_values), stored with its digest in
  // every checkpoint so that a resume can check it carries on the run that was started.
  void set_configuration(std::string resolved_values) { configuration_ = std::move(resolved_values); }

  // The run's wall clock and segments before this segment (run_record.hpp), added to the segment's
  // own clock in every checkpoint, so that a kill loses at most the time since the last one.
  void set_history(const RunHistory& history) { history_ = history; }
  const RunHistory& history() const { return history_; }
  // Wall clock since the recorder was made: the segment's (rank 0's clock, as the checkpoints').
  double segment_seconds() const;

  // Checkpoint metadata: the snapshots in snapshots.h5 when it was taken (a resume keeps that many),
  // the configuration and its digest.
  static constexpr const char* kSnapshotCount = "run.snapshot_count";
  static constexpr const char* kConfiguration = "run.resolved_toml";
  static constexpr const char* kConfigurationDigest = "run.config_digest";

  void progress(const StageProgress& p) override;
  void stage_finished(Stage stage, const std::string& summary) override;
  void snapshot_due(const std::string& label) override;
  void ground_reaction_row(const GroundReactionRow& row, const std::vector<GroundReactionRow>& rows) override;
  bool checkpoint_due() override;
  void checkpoint(const std::map<std::string, std::string>& state) override;
  bool stop_requested() override;

 private:
  TrapdoorExperiment& experiment_;
  RunFolder folder_;
  RunLog* log_;
  RunStopRules stop_;
  RunRanks* ranks_;
  double started_ = 0.0, last_checkpoint_ = 0.0;
  bool checkpoint_wanted_ = false;
  std::size_t snapshots_ = 0;       // in snapshots.h5
  std::string configuration_;
  RunHistory history_;
  std::int64_t calls_ = 0, stop_calls_ = 0;

  // Where the stage now running began in this segment (its first step, or the resume that carries
  // it on): each stage's end says what it cost, so a long run's log shows where its time went.
  struct StageMark {
    double seconds = 0.0;         // the segment's wall clock
    double particle_steps = 0.0;  // the run's particle-steps
    std::int64_t rebuilds = 0;    // neighbour-list rebuilds (this rank's)
    double rebuild_seconds = 0.0;
    bool resumed = false;         // the stage began in an earlier segment
  };
  std::optional<StageMark> stage_mark_;
  StageMark mark_now(bool resumed) const;
  void mark_stage_start();  // at the first progress line, before the first step: after a resume's restore
  std::string stage_cost();  // since the mark, and marks the next stage's start
};

// Seconds of a monotonic clock (durations are written by format_duration, run_progress.hpp).
double now_seconds();

}  // namespace trapdem
