#include "experiment/run_recorder.hpp"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/snapshot.hpp"
#include "experiment/run_identity.hpp"

namespace trapdem {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

RunRecorder::RunRecorder(TrapdoorExperiment& experiment, RunFolder folder, RunLog* log, RunStopRules stop,
                         RunRanks* ranks)
    : experiment_(experiment), folder_(std::move(folder)), log_(log), stop_(stop), ranks_(ranks) {
  started_ = last_checkpoint_ = now_seconds();
  on_root(ranks_, [&] {
    if (folder_.has_snapshots()) snapshots_ = list_snapshots(folder_.snapshots_h5()).size();
  });
}

double RunRecorder::segment_seconds() const { return now_seconds() - started_; }

void RunRecorder::progress(const StageProgress& p) {
  mark_stage_start();  // the experiment's first call, forced before its first step (after a resume's restore)
  say(progress_line(p));
}

RunRecorder::StageMark RunRecorder::mark_now(bool resumed) const {
  const Simulation& sim = experiment_.simulation();
  // Called inside the stage's last step, which the experiment counts once the step returns: its
  // particles are counted here, so the stages' particle-steps add up to run.json's.
  const double in_flight = sim.step_count() > 0 ? double(experiment_.particle_count()) : 0.0;
  return StageMark{segment_seconds(), experiment_.particle_steps_total() + (resumed ? 0.0 : in_flight),
                   sim.stats().rebuilds, sim.stats().rebuild_seconds, resumed};
}

void RunRecorder::mark_stage_start() {
  if (!stage_mark_) stage_mark_ = mark_now(experiment_.simulation().step_count() > 0);
}

std::string RunRecorder::stage_cost() {
  mark_stage_start();
  const StageMark start = *stage_mark_;
  const StageMark end = mark_now(false);
  stage_mark_ = end;
  const double seconds = end.seconds - start.seconds;
  const double particle_steps = end.particle_steps - start.particle_steps;
  const double rebuild_seconds = end.rebuild_seconds - start.rebuild_seconds;
  return fmt::format("  its cost{}: {} of wall clock, {:.4g} particle-steps ({:.2f} M/s), {} neighbour-list rebuilds "
                     "taking {:.1f} % of that wall clock",
                     start.resumed ? " since this segment's resume" : "", format_duration(seconds), particle_steps,
                     seconds > 0.0 ? particle_steps / seconds / 1e6 : 0.0, end.rebuilds - start.rebuilds,
                     seconds > 0.0 ? 100.0 * rebuild_seconds / seconds : 0.0);
}

void RunRecorder::stage_finished(Stage stage, const std::string& summary) {
  say(fmt::format("stage {} finished at t = {:.4f} s (step {}): {}", stage_name(stage),
                  experiment_.simulation().time(), experiment_.simulation().step_count(), summary));
  say(stage_cost());
  checkpoint_wanted_ = true;  // every stage end is a checkpoint
}

void RunRecorder::snapshot_due(const std::string& label) {
  const Simulation& sim = experiment_.simulation();
  const Particles gathered = ranks_ ? ranks_->gather(sim) : Particles{};
  const Particles& particles = ranks_ ? gathered : sim.particles();
  on_root(ranks_, [&] {
    const std::string name =
        append_snapshot(folder_.snapshots_h5(), make_snapshot(particles, sim.bodies(), sim.time(), label,
                                                              experiment_.trapdoor_displacement(), sim.step_count()));
    say(fmt::format("snapshot {} ({}, trapdoor at {} mm, {} particles)", name, label,
                    fixed_text(experiment_.trapdoor_displacement() * 1e3, 2), particles.size()));
  });
  ++snapshots_;
}

void RunRecorder::ground_reaction_row(const GroundReactionRow&, const std::vector<GroundReactionRow>& rows) {
  on_root(ranks_, [&] { write_text_atomically(folder_.trapdoor_csv(), ground_reaction_csv(rows)); });
}

bool RunRecorder::checkpoint_due() {
  if (++calls_ % 256 != 0 && !checkpoint_wanted_) return false;
  if (checkpoint_wanted_) return true;
  const bool due = now_seconds() - last_checkpoint_ >= experiment_.config().output.checkpoint_interval;
  return ranks_ ? ranks_->broadcast(due) : due;  // rank 0's clock decides for all
}

void RunRecorder::checkpoint(const std::map<std::string, std::string>& state) {
  auto metadata = state;
  metadata["run.name"] = experiment_.config().name;
  metadata[kSnapshotCount] = std::to_string(snapshots_);
  history_.store(metadata, segment_seconds());
  if (!configuration_.empty()) {
    metadata[kConfiguration] = configuration_;
    metadata[kConfigurationDigest] = config_digest(configuration_);
  }
  if (ranks_)
    ranks_->save_checkpoint(folder_.checkpoint_h5(), experiment_.simulation(), metadata);
  else
    save_checkpoint(folder_.checkpoint_h5(), experiment_.simulation(), std::move(metadata));
  last_checkpoint_ = now_seconds();
  checkpoint_wanted_ = false;
  if (log_)
    log_->note(fmt::format("checkpoint at t = {:.6f} s (step {}, stage {})", experiment_.simulation().time(),
                           experiment_.simulation().step_count(), stage_name(experiment_.stage())));
}

bool RunRecorder::stop_requested() {
  if (stop_.at_step > 0 && experiment_.simulation().step_count() >= stop_.at_step) return true;
  if (ranks_) {
    // A signal reaches the ranks at different steps and each rank has its own clock: every 64
    // calls the ranks agree, so all stop (with a checkpoint) at the same step.
    if (++stop_calls_ % 64 != 0) return false;
    const bool local = (stop_.signal && *stop_.signal != 0) ||
                       (stop_.after_seconds > 0.0 && now_seconds() - started_ >= stop_.after_seconds);
    return ranks_->any(local);
  }
  if (stop_.signal && *stop_.signal != 0) return true;
  return stop_.after_seconds > 0.0 && (++stop_calls_ % 64 == 0) && now_seconds() - started_ >= stop_.after_seconds;
}

}  // namespace trapdem
