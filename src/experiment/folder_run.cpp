#include "experiment/folder_run.hpp"

#include <omp.h>

#include <atomic>
#include <csignal>
#include <optional>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/thread_count.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_log.hpp"
#include "experiment/run_record.hpp"
#include "experiment/run_recorder.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/snapshot.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

std::atomic<int> g_signal{0};
extern "C" void on_signal(int sig) { g_signal = sig; }

// Snapshots written after the checkpoint would be written again by the resumed run: drop them.
void drop_snapshots_after(const fs::path& h5, std::int64_t step) {
  if (!fs::exists(h5)) return;
  const auto infos = list_snapshots(h5);
  bool any_later = false;
  for (const auto& info : infos) any_later = any_later || info.step > step;
  if (!any_later) return;
  std::vector<Snapshot> keep;
  for (const auto& info : infos)
    if (info.step <= step) keep.push_back(read_snapshot(h5, info.name));
  const fs::path fresh = h5.parent_path() / (".resume-" + h5.filename().string());
  fs::remove(fresh);
  for (const Snapshot& s : keep) append_snapshot(fresh, s);
  if (keep.empty()) {
    fs::remove(h5);
  } else {
    fs::rename(fresh, h5);
  }
  write_snapshot_xdmf(h5);
}

// The run's description at the top of run.log.
void describe_run(RunLog& recorder, const ExperimentConfig& c, const fs::path& out) {
  recorder.say(fmt::format("trapdem run '{}': {}", c.name, c.description));
  recorder.say(fmt::format("  box {:.1f} x {:.1f} x {:.1f} mm ({}), trapdoor {:.1f} mm at x = {:.1f} mm, travel {:.1f} mm "
                           "at {:.4g} m/s", c.box.width * 1e3, c.box.depth * 1e3, c.box.height * 1e3,
                           c.box.periodic_depth ? "periodic depth" : "front and back walls", c.trapdoor.width * 1e3,
                           c.trapdoor.centre * 1e3, c.trapdoor.travel * 1e3, c.trapdoor.rate));
  recorder.say(fmt::format("  particles: {}, density {} kg/m3, about {} of them; k_n = {:.3g} N/m, e = {}, mu_s = {}, "
                           "mu_k = {}, mu_r = {} ({})", c.material.sizes.describe(), c.material.density,
                           c.expected_particle_count(), c.material.particle.normal_stiffness,
                           c.material.particle.restitution, c.material.particle.static_friction,
                           c.material.particle.kinetic_friction, c.material.particle.rolling_friction,
                           to_string(c.material.particle.rolling_model)));
  recorder.say(fmt::format("  time step {:.4g} s ({:.3g} of the critical {:.4g} s), skin {:.3g} mm, {} g, {} threads",
                           c.time_step(), c.time_step() / c.critical_time_step(), c.critical_time_step(),
                           c.skin() * 1e3, c.spin_up.g_level, omp_get_max_threads()));
  recorder.say(fmt::format("  output in {}", out.string()));
}

// The run once its folder's log is open (`log` is emplaced as soon as the folder is known).
bool run_logged(const FolderRunOptions& o, std::optional<RunLog>& log) {
  const bool resume = !o.resume_dir.empty();
  fs::path out;
  Config config = [&] {
    if (resume) {
      out = o.resume_dir;
      const RunFolder folder(out);
      if (!folder.has_checkpoint())
        throw InputError(fmt::format("--resume {}: no checkpoint.h5 there to resume from", out.string()));
      log.emplace(folder.run_log(), o.quiet);
      log->say(fmt::format("trapdem run --resume {}", out.string()));
      return Config::load_file(folder.resolved_toml().string());
    }
    return Config::load_file(o.config_file.string());
  }();
  config.apply_overrides(o.overrides);
  const ExperimentConfig experiment_config = ExperimentConfig::from(config);
  const int threads = o.threads > 0 ? o.threads : experiment_config.numerics.threads;
  if (threads > 0) omp_set_num_threads(threads);
  if (!resume) {
    out = o.out_dir.empty() ? fs::path("trapdem-out") / experiment_config.name : o.out_dir;
    const RunFolder folder(out);
    if (folder.has_checkpoint() || folder.has_snapshots())
      throw InputError(fmt::format("{} already holds a run: resume it with --resume {}, or choose another --out",
                                   out.string(), out.string()));
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", out.string(), ec.message()));
    log.emplace(folder.run_log(), o.quiet);  // before anything else is written: the log from its first line
    describe_run(*log, experiment_config, out);
    write_text_atomically(folder.resolved_toml(), config.resolved_toml());
  }
  const RunFolder folder(out);

  TrapdoorExperiment experiment(experiment_config);
  RunRecorder recorder(experiment, folder, *log, RunStopRules{&g_signal, o.stop_after_seconds, o.stop_at_step});
  if (resume) {
    Checkpoint ckpt = read_checkpoint(folder.checkpoint_h5());
    const auto metadata = ckpt.metadata;
    const std::int64_t step = ckpt.stats.steps;
    restore_checkpoint(experiment.simulation(), std::move(ckpt));
    experiment.restore(metadata);
    drop_snapshots_after(folder.snapshots_h5(), step);
    write_text_atomically(folder.trapdoor_csv(), ground_reaction_csv(experiment.ground_reaction()));
    recorder.say(fmt::format("resumed {} at t = {:.6f} s (step {}, stage {})", out.string(),
                             experiment.simulation().time(), step, stage_name(experiment.stage())));
  }

  g_signal = 0;
  auto previous_int = std::signal(SIGINT, on_signal);
  auto previous_term = std::signal(SIGTERM, on_signal);
  const double start = now_seconds();
  const std::int64_t start_steps = experiment.simulation().step_count();
  bool complete = false;
  try {
    complete = experiment.run(recorder);
  } catch (...) {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
    throw;
  }
  std::signal(SIGINT, previous_int);
  std::signal(SIGTERM, previous_term);
  const double seconds = now_seconds() - start;
  const Simulation& sim = experiment.simulation();
  recorder.say(fmt::format("{} after {} of wall clock: {} steps, {} particles, {:.2f} M particle-steps/s",
                           complete ? "finished" : "stopped (checkpoint written; carry on with --resume)",
                           format_duration(seconds), sim.step_count() - start_steps, sim.particles().size(),
                           seconds > 0 ? double(sim.particles().size()) * double(sim.step_count() - start_steps) / seconds / 1e6 : 0.0));
  if (complete) {
    std::map<std::string, std::string> state = experiment.state();
    recorder.checkpoint(state);  // the final state, so a later analysis or extension can start from it
  }
  record_run_segment(folder, RunSegment{complete, stage_name(experiment.stage()), seconds,
                                        sim.step_count() - start_steps, experiment.particle_steps_run(),
                                        sim.particles().size()});
  return complete;
}

}  // namespace

bool run_in_folder(const FolderRunOptions& o) {
  checked_thread_count(o.threads, "--threads");
  std::optional<RunLog> log;
  try {
    return run_logged(o, log);
  } catch (const std::exception& e) {
    // The error that stops the run belongs in its log too (if the log itself failed, it cannot).
    if (log) {
      try {
        log->note(fmt::format("stopped by an error: {}", e.what()));
      } catch (const FileError&) {
      }
    }
    throw;
  }
}

}  // namespace trapdem
