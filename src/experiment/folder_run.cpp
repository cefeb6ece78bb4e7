#include "experiment/folder_run.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>
#include <optional>

#include <fmt/format.h>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/host_load.hpp"
#include "core/wait_policy.hpp"
#include "dem/thread_scope.hpp"
#include "core/nearest_name.hpp"
#include "core/thread_count.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_identity.hpp"
#include "experiment/run_log.hpp"
#include "experiment/run_progress.hpp"
#include "experiment/run_ranks.hpp"
#include "experiment/run_record.hpp"
#include "experiment/run_recorder.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/folder_lock.hpp"
#include "io/snapshot.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

std::atomic<int> g_signal{0};
extern "C" void on_signal(int sig) { g_signal = sig; }

// A resume keeps the snapshots the checkpoint saw (`count`, its metadata) and drops the rest: a
// snapshot written after the checkpoint, even at the checkpoint's own step (the first lowering
// snapshot follows the stage-end checkpoint), is written again by the resumed run. Checkpoints of
// an older version have no count: there the snapshots after the checkpoint's step go.
void cut_snapshots_to_checkpoint(const fs::path& h5, std::optional<std::size_t> count, std::int64_t step) {
  if (count) keep_snapshots(h5, *count);
  else truncate_snapshots(h5, step);
  // A resume of an earlier version rebuilt the file beside it; a kill then left this behind.
  std::error_code ec;
  fs::remove(h5.parent_path() / (".resume-" + fs::path(h5).replace_extension(".xmf").filename().string()), ec);
}

// The run's description at the top of run.log.
void describe_run(RunLog& recorder, const ExperimentConfig& c, const fs::path& out) {
  recorder.say(fmt::format("trapdem run '{}': {}", c.name, c.description));
  recorder.say(fmt::format("  box {:.1f} x {:.1f} x {:.1f} mm ({}), trapdoor {:.1f} mm at x = {:.1f} mm, travel {:.1f} mm "
                           "at {:.4g} m/s", c.box.width * 1e3, c.box.depth * 1e3, c.box.height * 1e3,
                           c.box.periodic_depth ? "periodic depth" : "front and back walls", c.trapdoor.width * 1e3,
                           c.trapdoor.centre * 1e3, c.trapdoor.travel * 1e3, c.trapdoor.rate));
  recorder.say(fmt::format("  particles: {}, density {} kg/m3, about {} of them; contact law {}", c.material.sizes.describe(),
                           c.material.density, c.expected_particle_count(), describe_law(c.material.particle)));
  if (c.material.shape.is_clump())
    recorder.say(fmt::format("  shape: {}; sizes are volume-equivalent diameters", c.material.shape.describe()));
  for (const std::string& key : c.material.unread_parameters)
    recorder.say(fmt::format("  note: {} is given but not read by its contact law", key));
  // The constant torque's one-step bound lets a contact under a steady torque creep at T dt / I, so
  // its strength in shear depends on the step (docs/element.md, "Rolling resistance and the time
  // step"); mu_r 0.001 (Calibrated) does not matter, mu_r 0.2 does.
  const ContactLaw& law = c.material.particle;
  if (law.rolling_model == RollingModel::constant_torque && law.rolling_friction >= 0.01)
    recorder.say(fmt::format("  note: constant_torque rolling resistance is weaker at a longer step (here step / mean "
                             "diameter = {:.2g}; RF3 at 50 kPa: phi'_cs 31.5 deg at 3.9e-4, 24.0 at 2.7e-3, 36.8 at 7.5e-5; "
                             "docs/element.md): state its element-test strength at this step, or use elastic_plastic",
                             c.time_step() / c.material.sizes.mean_diameter()));
  const bool own_pour_skin = !c.packing.particles && c.pour_skin() != c.skin();
  const std::string pour_skin = own_pour_skin ? fmt::format(" ({:.3g} mm while pouring)", c.pour_skin() * 1e3) : "";
  recorder.say(fmt::format("  time step {:.4g} s ({:.3g} of the critical {:.4g} s), skin {:.3g} mm{}, {} g, {}",
                           c.time_step(), c.time_step() / c.critical_time_step(), c.critical_time_step(),
                           c.skin() * 1e3, pour_skin, c.spin_up.g_level, threads_text(omp_get_max_threads())));
  if (c.packing.particles)
    recorder.say(fmt::format("  from the packing {} ({}, {} particles, shift [{}, {}, {}] m): no pour, starting at {}",
                             c.packing.from, c.packing.format, c.packing.particles->size(), c.packing.shift.x,
                             c.packing.shift.y, c.packing.shift.z, c.packing.start_at_spin_up ? "spin-up" : "settling"));
  recorder.say(fmt::format("  trapdem {}, on {}", describe_build(), describe_cpu()));
  recorder.say(fmt::format("  output in {}", out.string()));
}

// The key of a --set assignment ("trapdoor.rate=0.02" -> "trapdoor.rate").
std::string override_key(const std::string& assignment) {
  std::string key = assignment.substr(0, assignment.find('='));
  const auto first = key.find_first_not_of(" \t"), last = key.find_last_not_of(" \t");
  return first == std::string::npos ? "" : key.substr(first, last - first + 1);
}

bool allowed(const FolderRunOptions& o, const std::string& key) {
  return std::find(o.allowed_changes.begin(), o.allowed_changes.end(), key) != o.allowed_changes.end();
}

// --resume takes the folder's configuration: no other file, and a --set only for a key named by
// --allow-change.
void check_resume_options(const FolderRunOptions& o) {
  if (o.resume_dir.empty()) {
    if (!o.allowed_changes.empty())
      throw InputError(fmt::format("--allow-change {}: only with --resume DIR (a new run takes any --set)",
                                   o.allowed_changes.front()));
    return;
  }
  if (!o.config_file.empty() || !o.config_text.empty())
    throw InputError(fmt::format("--resume {} carries on the run with the folder's resolved.toml: give no configuration "
                                 "file or --preset with it ({})", o.resume_dir.string(),
                                 o.config_text.empty() ? o.config_file.string() : o.config_name));
  for (const std::string& assignment : o.overrides)
    if (!allowed(o, override_key(assignment)))
      throw InputError(fmt::format("--set {}: --resume carries on the run that was started, with its configuration; to "
                                   "change {} on purpose add --allow-change {} (the change is logged in run.log and "
                                   "recorded in resolved.toml)",
                                   assignment, override_key(assignment), override_key(assignment)));
}

// The temporaries of writes a kill interrupted: io/atomic_file.cpp writes FILE through
// ".FILE.tmp-PID-N" beside it (checkpoint.h5, snapshots.h5, snapshots/NNNNNN.h5) and renames it;
// a kill before the rename leaves it (a snapshot's is ~26 MB at paper scale). Called with the
// folder's lock held, so no other process is writing one. Returns how many were removed.
int remove_interrupted_writes(const RunFolder& folder) {
  int removed = 0;
  for (const fs::path& dir : {folder.path(), folder.path() / "snapshots"}) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos && e.is_regular_file(ec) &&
          fs::remove(e.path(), ec))
        ++removed;
    }
  }
  return removed;
}

// The checkpoints a run.log records as complete (RunRecorder notes "checkpoint at t = ... (step N,
// stage ...)" once checkpoint.h5 is written): told apart from a run killed before its first one.
struct CheckpointsLogged {
  int count = 0;
  std::int64_t last_step = 0;
};
CheckpointsLogged checkpoints_logged(const fs::path& run_log) {
  CheckpointsLogged logged;
  std::ifstream in(run_log);
  const std::string mark = "checkpoint at t = ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(mark, 0) != 0) continue;
    const std::size_t step = line.find("(step ");
    if (step == std::string::npos) continue;
    ++logged.count;
    logged.last_step = std::atoll(line.c_str() + step + 6);
  }
  return logged;
}

// Each --allow-change names a key of the run's configuration: a misspelt one would otherwise let
// nothing through and say nothing (issue 41).
void check_allowed_changes_are_keys(const FolderRunOptions& o, const std::string& configuration) {
  if (o.allowed_changes.empty()) return;
  std::vector<std::string> keys;
  for (const auto& [key, value] : value_leaves(configuration, "resolved.toml")) keys.push_back(key);
  for (const std::string& key : o.allowed_changes) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    const std::string nearest = nearest_name(key, keys);
    throw InputError(fmt::format("--allow-change {}: not a key of this run's configuration{}", key,
                                 nearest.empty() ? " (resolved.toml lists them)" : fmt::format(" (did you mean {}?)", nearest)));
  }
}

// A resume's configuration against the one its checkpoint was taken with: a change of a key not
// named by --allow-change is refused, naming the first; allowed changes are logged and recorded.
void check_configuration(const FolderRunOptions& o, const std::map<std::string, std::string>& metadata,
                         const std::string& now, const RunFolder& folder, const Config& config, RunLog& log,
                         std::int64_t step) {
  const auto stored = metadata.find(RunRecorder::kConfiguration);
  if (stored == metadata.end()) {
    log.say("note: the checkpoint was written by an older trapdem and holds no configuration; resolved.toml is taken "
            "as it is");
    return;
  }
  const auto digest = metadata.find(RunRecorder::kConfigurationDigest);
  if (digest != metadata.end() && digest->second == config_digest(now)) return;  // the same run
  // The checkpoint's configuration as this trapdem reads it: a key added since it was written comes
  // in at its default, which keeps the old behaviour, and is no change. A text this trapdem no
  // longer reads is compared as it is: the retired key is then named as a change.
  std::string started = stored->second;
  try {
    started = as_read_now(stored->second, "the checkpoint's configuration");
  } catch (const InputError&) {
  }
  const std::vector<ConfigChange> changes = config_changes(started, now);
  for (const ConfigChange& c : changes) {
    if (allowed(o, c.key)) continue;
    throw InputError(fmt::format(
        "--resume {}: the configuration differs from the run that was started: {} was {} at the checkpoint, is {} now "
        "({}); a resumed run must be the run that was started: restore the value, or add --allow-change {} to "
        "change it on purpose", o.resume_dir.string(), c.key, c.before, c.after,
        changes.size() > 1 ? fmt::format("and {} more key(s) differ", changes.size() - 1) : "the only difference",
        c.key));
  }
  std::string record;
  for (const ConfigChange& c : changes) {
    log.say(fmt::format("changed on resume at step {} (--allow-change): {} = {} (was {})", step, c.key, c.after, c.before));
    record += fmt::format("# changed on resume at step {} (--allow-change): {} = {} (was {})\n", step, c.key, c.after,
                          c.before);
  }
  write_text_atomically(folder.resolved_toml(), record + config.resolved_toml());
}

// run.log on ranks: each rank's particles and halo in this segment (ghosts held per step, the
// wall clock of the exchanges per step), the measured inputs of the weak-scaling model
// (bench/RESULTS.md).
void report_halo(RunRecorder& recorder, RunRanks& ranks, const Simulation& sim, std::int64_t steps) {
  const SimulationStats& s = sim.stats();
  const double per_step = 1.0 / double(std::max<std::int64_t>(steps, 1));
  const std::vector<double> all = ranks.gather_on_root(
      {double(sim.owned_count()), double(s.ghost_steps) * per_step, s.exchange_seconds * per_step});
  for (std::size_t r = 0; 3 * r + 2 < all.size(); ++r)
    recorder.say(fmt::format("  rank {}: {:.0f} particles, {:.0f} ghosts per step on average, exchanges {:.1f} us per step",
                             r, all[3 * r], all[3 * r + 1], all[3 * r + 2] * 1e6));
}

// Warns in run.log and on the terminal when the threads of this run (x its ranks on this host) and
// of the other trapdem runs registered on the host exceed its usable cores. On ranks every rank is
// registered before rank 0 reads the registry (the gather waits for all), and its sibling ranks
// are counted once, as this run's.
void warn_if_host_oversubscribed(RunRanks* ranks, std::optional<RunLog>& log) {
  std::vector<double> sibling_pids{double(::getpid())};
  if (ranks) sibling_pids = ranks->gather_on_root(sibling_pids);
  if (ranks && !ranks->root()) return;
  HostLoad load = current_host_load(omp_get_max_threads(), ranks ? local_rank_count() : 1);
  std::erase_if(load.others, [&](const RegisteredRun& other) {
    return std::find(sibling_pids.begin(), sibling_pids.end(), double(other.pid)) != sibling_pids.end();
  });
  if (const std::string warning = load.warning(wait_policy(), passive_restart_failed()); !warning.empty() && log) log->warn(warning);
}

// Takes the run folder's lock before anything in it is written: a second process on the same
// folder (a study submitted twice, a hand resume beside a running Slurm task) is refused instead of
// both overwriting its checkpoint.h5 and snapshots.
void lock_run_folder(std::optional<FolderLock>& lock, const RunFolder& folder) {
  lock.emplace(folder.run_lock(),
               "two runs in one folder would overwrite each other's checkpoint and snapshots; wait until it ends "
               "(a study's Slurm task: squeue), or stop it (SIGINT/SIGTERM write a checkpoint) and resume then");
}

// The run once its folder's log is open (`log` is emplaced as soon as the folder is known). On
// ranks every rank reads the configuration; the folder's checks and files are rank 0's, and each
// step of the set-up is agreed on (an error on one rank is thrown on all).
bool run_logged(const FolderRunOptions& o, std::optional<RunLog>& log) {
  RunRanks* const ranks = o.ranks;
  const bool root = !ranks || ranks->root();
  bool resume = !o.resume_dir.empty();
  fs::path out;
  bool restart = false;  // --resume of a folder without checkpoint.h5
  CheckpointsLogged lost_checkpoints;  // what run.log says was written of the missing checkpoint.h5
  std::optional<Config> loaded;
  std::optional<FolderLock> lock;  // held by rank 0 until the run's last line (folder_lock.hpp)
  agreed(ranks, [&] {
    check_resume_options(o);
    if (resume) {
      out = o.resume_dir;
      const RunFolder folder(out);
      if (root) {
        if (!folder.has_checkpoint() && !fs::exists(folder.resolved_toml()))
          throw InputError(fmt::format("--resume {}: neither checkpoint.h5 nor resolved.toml there: not a run folder",
                                       out.string()));
        lock_run_folder(lock, folder);
        restart = !folder.has_checkpoint();
        if (restart) lost_checkpoints = checkpoints_logged(folder.run_log());
        log.emplace(folder.run_log(), o.quiet, o.terminal);
        log->say(fmt::format("trapdem run --resume {}", out.string()));
        if (const int removed = remove_interrupted_writes(folder); removed > 0)
          log->say(fmt::format("removed {} temporary file{} of a write the stop interrupted", removed,
                               removed == 1 ? "" : "s"));
      }
      loaded = Config::load_file(folder.resolved_toml().string());
    } else {
      loaded = o.config_text.empty() ? Config::load_file(o.config_file.string()) : Config::parse(o.config_text, o.config_name);
    }
  });
  if (ranks) restart = ranks->broadcast(restart);
  Config& config = *loaded;
  std::optional<ExperimentConfig> read;
  std::string configuration;
  agreed(ranks, [&] {
    config.apply_overrides(o.overrides);
    read = ExperimentConfig::from(config);
    configuration = resolved_values(config);
    check_allowed_changes_are_keys(o, configuration);
  });
  const ExperimentConfig& experiment_config = *read;
  const ThreadScope threads(o.threads > 0 ? o.threads : experiment_config.numerics.threads);
  if (restart) resume = false;
  if (!resume && o.resume_dir.empty())
    out = o.out_dir.empty() ? fs::path("trapdem-out") / experiment_config.name : o.out_dir;
  const RunFolder folder(out);
  std::optional<Checkpoint> ckpt;
  on_root(ranks, [&] {
    if (restart) {
      // Killed before its first checkpoint (during it, or earlier): nothing to carry on, so the run
      // starts again from the beginning in the same folder; what it wrote so far is written anew.
      // Said also under --quiet: the run's results so far are written anew.
      if (lost_checkpoints.count == 0)
        log->warn(fmt::format("no checkpoint.h5 in {} (the run stopped before its first checkpoint was complete): "
                              "starting it again from the beginning with its resolved.toml", out.string()));
      else
        log->warn(fmt::format("checkpoint.h5 is missing from {}, although run.log records {} completed checkpoint{} "
                              "(the last at step {}): it was deleted or moved; starting the run again from the "
                              "beginning with its resolved.toml",
                              out.string(), lost_checkpoints.count, lost_checkpoints.count == 1 ? "" : "s",
                              lost_checkpoints.last_step));
      for (const fs::path& p : {folder.snapshots_h5(), fs::path(folder.snapshots_h5()).replace_extension(".xmf"),
                                folder.trapdoor_csv()})
        fs::remove(p);
    } else if (!resume) {
      if (folder.has_checkpoint() || folder.has_snapshots())
        throw InputError(fmt::format("{} already holds a run: resume it with --resume {}, or choose another --out",
                                     out.string(), out.string()));
      std::error_code ec;
      fs::create_directories(out, ec);
      if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", out.string(), ec.message()));
      lock_run_folder(lock, folder);
      log.emplace(folder.run_log(), o.quiet, o.terminal);  // before anything else is written: the log from its first line
    }
    if (resume) {
      ckpt = read_checkpoint(folder.checkpoint_h5());
      check_configuration(o, ckpt->metadata, configuration, folder, config, *log, ckpt->stats.steps);
      std::optional<std::size_t> count;
      if (auto it = ckpt->metadata.find(RunRecorder::kSnapshotCount); it != ckpt->metadata.end())
        count = std::stoul(it->second);
      cut_snapshots_to_checkpoint(folder.snapshots_h5(), count, ckpt->stats.steps);
    } else {
      describe_run(*log, experiment_config, out);
      if (ranks) log->say(fmt::format("  on {} ranks (MPI), each with the threads above", ranks->ranks()));
      std::string record;
      for (const std::string& key : o.allowed_changes)
        record += fmt::format("# --allow-change {} given at a restart from the beginning\n", key);
      write_text_atomically(folder.resolved_toml(), record + config.resolved_toml());
    }
  });

  // This run in the host's run registry while it lives, and a warning when it and the others
  // registered there ask for more threads than the host has cores (host_load.hpp).
  const RunRegistration registration(omp_get_max_threads(), fs::absolute(out).lexically_normal().string());
  warn_if_host_oversubscribed(ranks, log);

  std::optional<TrapdoorExperiment> built;
  agreed(ranks, [&] {
    built.emplace(experiment_config);
    if (ranks) built->attach_decomposition(ranks->decomposition());
  });
  TrapdoorExperiment& experiment = *built;
  RunRecorder recorder(experiment, folder, log ? &*log : nullptr,
                       RunStopRules{&g_signal, o.stop_after_seconds, o.stop_at_step}, ranks);
  recorder.set_configuration(configuration);
  on_root(ranks, [&] {
    // What the run did before this segment: the checkpoint's record of it (a killed segment counts
    // up to its last checkpoint), or, from an older trapdem's checkpoint, run.json's.
    if (resume) {
      const std::optional<RunHistory> stored = RunHistory::from(ckpt->metadata);
      recorder.set_history(stored ? *stored : RunHistory::from_record(folder));
    }
  });
  if (resume) {
    std::map<std::string, std::string> metadata;
    if (ranks) {
      metadata = ranks->restore_checkpoint(std::move(ckpt), experiment.simulation());
    } else {
      metadata = ckpt->metadata;
      restore_checkpoint(experiment.simulation(), std::move(*ckpt));
    }
    agreed(ranks, [&] { experiment.restore(metadata); });
    on_root(ranks, [&] {
      write_text_atomically(folder.trapdoor_csv(), ground_reaction_csv(experiment.ground_reaction()));
    });
    recorder.say(fmt::format("resumed {} at t = {:.6f} s (step {}, stage {})", out.string(),
                             experiment.simulation().time(), experiment.simulation().step_count(),
                             stage_name(experiment.stage())));
  }

  g_signal = 0;
  auto previous_int = std::signal(SIGINT, on_signal);
  auto previous_term = std::signal(SIGTERM, on_signal);
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
  const double seconds = recorder.segment_seconds();  // from before the checkpoint's restore, as checkpoints count
  const Simulation& sim = experiment.simulation();
  const std::size_t particles = experiment.particle_count();
  if (complete) {
    std::map<std::string, std::string> state = experiment.state();
    recorder.checkpoint(state);  // the final state, so a later analysis or extension can start from it
  }
  // The last line's rate is run.json's: the run's particle-steps over its wall clock, every segment.
  double per_second = 0.0;
  on_root(ranks, [&] {
    per_second = record_run_segment(folder,
                                    RunSegment{complete, stage_name(experiment.stage()), seconds, sim.step_count(),
                                               experiment.particle_steps_total(), particles, omp_get_max_threads(),
                                               ranks ? ranks->ranks() : 1},
                                    recorder.history());
  });
  recorder.say(fmt::format("{} after {} of wall clock: {} steps, {} particles, {:.2f} M particle-steps/s{}",
                           complete ? "finished" : "stopped (checkpoint written; carry on with --resume)",
                           format_duration(seconds), sim.step_count() - start_steps, particles, per_second / 1e6,
                           resume ? " (the whole run's, as run.json)" : ""));
  if (ranks) report_halo(recorder, *ranks, sim, sim.step_count() - start_steps);
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
