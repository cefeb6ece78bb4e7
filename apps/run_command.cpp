#include "run_command.hpp"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "core/json.hpp"
#include "core/errors.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"
#include "io/snapshot.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

namespace {

std::atomic<int> g_signal{0};
extern "C" void on_signal(int sig) { g_signal = sig; }

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string format_duration(double s) {
  if (s < 0.0) return "?";
  if (s < 120.0) return fmt::format("{:.0f} s", s);
  if (s < 7200.0) return fmt::format("{:.1f} min", s / 60.0);
  return fmt::format("{:.1f} h", s / 3600.0);
}

// Writes the run's files as the experiment reports its events.
class RunRecorder : public ExperimentObserver {
 public:
  RunRecorder(TrapdoorExperiment& experiment, fs::path out, bool quiet, double stop_after, std::int64_t stop_at_step)
      : experiment_(experiment), out_(std::move(out)), quiet_(quiet), stop_after_(stop_after), stop_at_step_(stop_at_step) {
    log_.open(out_ / "run.log", std::ios::app);
    if (!log_) throw FileError(fmt::format("cannot open {} for writing", (out_ / "run.log").string()));
    started_ = last_checkpoint_ = now_seconds();
  }

  void say(const std::string& line) {
    if (!quiet_) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    }
    log_ << line << '\n';
    log_.flush();
  }

  void progress(const StageProgress& p) override {
    say(fmt::format("[{:<10}] {:5.1f}%  t = {:.4f} s  {:6.2f} M particle-steps/s  left {:>8}  {}", stage_name(p.stage),
                    100.0 * p.fraction, p.simulated_time, p.particle_steps_per_second / 1e6,
                    format_duration(p.seconds_left), p.detail));
  }

  void stage_finished(Stage stage, const std::string& summary) override {
    say(fmt::format("stage {} finished at t = {:.4f} s (step {}): {}", stage_name(stage),
                    experiment_.simulation().time(), experiment_.simulation().step_count(), summary));
    checkpoint_wanted_ = true;  // every stage end is a checkpoint
  }

  void snapshot_due(const std::string& label) override {
    const Simulation& sim = experiment_.simulation();
    const std::string name = append_snapshot(out_ / "snapshots.h5", make_snapshot(sim.particles(), sim.time(), label,
                                                                                  experiment_.trapdoor_displacement(),
                                                                                  sim.step_count()));
    say(fmt::format("snapshot {} ({}, trapdoor at {:.2f} mm, {} particles)", name, label,
                    experiment_.trapdoor_displacement() * 1e3, sim.particles().size()));
  }

  void ground_reaction_row(const GroundReactionRow&, const std::vector<GroundReactionRow>& rows) override {
    write_text_atomically(out_ / "trapdoor.csv", ground_reaction_csv(rows));
  }

  bool checkpoint_due() override {
    if (++calls_ % 256 != 0 && !checkpoint_wanted_) return false;
    return checkpoint_wanted_ || now_seconds() - last_checkpoint_ >= experiment_.config().output.checkpoint_interval;
  }

  void checkpoint(const std::map<std::string, std::string>& state) override {
    auto metadata = state;
    metadata["run.name"] = experiment_.config().name;
    save_checkpoint(out_ / "checkpoint.h5", experiment_.simulation(), std::move(metadata));
    last_checkpoint_ = now_seconds();
    checkpoint_wanted_ = false;
    log_ << fmt::format("checkpoint at t = {:.6f} s (step {}, stage {})\n", experiment_.simulation().time(),
                        experiment_.simulation().step_count(), stage_name(experiment_.stage()));
    log_.flush();
  }

  bool stop_requested() override {
    if (g_signal != 0) return true;
    if (stop_at_step_ > 0 && experiment_.simulation().step_count() >= stop_at_step_) return true;
    return stop_after_ > 0.0 && (++stop_calls_ % 64 == 0) && now_seconds() - started_ >= stop_after_;
  }

 private:
  TrapdoorExperiment& experiment_;
  fs::path out_;
  bool quiet_;
  double stop_after_;
  std::int64_t stop_at_step_;
  std::ofstream log_;
  double started_ = 0.0, last_checkpoint_ = 0.0;
  bool checkpoint_wanted_ = false;
  std::int64_t calls_ = 0, stop_calls_ = 0;
};

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

// run.json: the run's work so far, summed over its segments (a first run and each --resume that
// ended, finished or stopped); a segment ended by a kill is not counted. Studies read it.
void record_segment(const fs::path& out, bool complete, const std::string& stage, double seconds, std::int64_t steps,
                    double particle_steps, std::size_t particles) {
  const fs::path file = out / "run.json";
  double total_seconds = seconds, total_particle_steps = particle_steps;
  double total_steps = double(steps), segments = 1.0;
  if (fs::exists(file)) {
    try {
      const Json previous = Json::parse(read_text_file(file), file.string());
      total_seconds += previous["wall_seconds"].as_number();
      total_steps += previous["steps"].as_number();
      total_particle_steps += previous["particle_steps"].as_number();
      segments += previous["segments"].as_number();
    } catch (const InputError&) {
      // An unreadable record (written by another version) restarts the count: the run's results stand.
    }
  }
  Json j = Json::object();
  j.set("complete", complete);
  j.set("stage", stage);
  j.set("segments", segments);
  j.set("wall_seconds", total_seconds);
  j.set("steps", total_steps);
  j.set("particle_steps", total_particle_steps);
  j.set("particles", particles);
  j.set("particle_steps_per_second", total_seconds > 0.0 ? total_particle_steps / total_seconds : 0.0);
  write_text_atomically(file, j.dump() + "\n");
}

}  // namespace

fs::path preset_directory() {
  if (const char* env = std::getenv("TRAPDEM_PRESETS")) return env;
  return TRAPDEM_PRESET_DIR;
}

fs::path preset_path(const std::string& name) {
  const fs::path path = preset_directory() / (name + ".toml");
  if (!fs::exists(path)) {
    std::string known;
    if (fs::is_directory(preset_directory()))
      for (const auto& e : fs::directory_iterator(preset_directory()))
        if (e.path().extension() == ".toml") known += (known.empty() ? "" : ", ") + e.path().stem().string();
    throw InputError(fmt::format("no preset named '{}' in {} (presets: {})", name, preset_directory().string(), known));
  }
  return path;
}

int list_presets() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(preset_directory()))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    Config c = Config::load_file(f.string());
    fmt::print("{:<18} {}\n", f.stem().string(), c.get_string("description", ""));
  }
  return 0;
}

int run_experiment(const RunOptions& o) {
  const bool resume = !o.resume_dir.empty();
  fs::path out;
  Config config = [&] {
    if (resume) {
      out = o.resume_dir;
      if (!fs::exists(out / "checkpoint.h5"))
        throw InputError(fmt::format("--resume {}: no checkpoint.h5 there to resume from", out.string()));
      return Config::load_file((out / "resolved.toml").string());
    }
    if (!o.config_file.empty() && !o.preset.empty())
      throw InputError("give either a configuration file or --preset, not both");
    const std::string file = !o.config_file.empty() ? o.config_file : preset_path(o.preset.empty() ? "demo" : o.preset).string();
    return Config::load_file(file);
  }();
  config.apply_overrides(o.overrides);
  const ExperimentConfig experiment_config = ExperimentConfig::from(config);
  if (!resume) {
    out = o.out_dir.empty() ? fs::path("trapdem-out") / experiment_config.name : fs::path(o.out_dir);
    if (fs::exists(out / "checkpoint.h5") || fs::exists(out / "snapshots.h5"))
      throw InputError(fmt::format("{} already holds a run: resume it with --resume {}, or choose another --out",
                                   out.string(), out.string()));
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", out.string(), ec.message()));
    write_text_atomically(out / "resolved.toml", config.resolved_toml());
  }

  const int threads = o.threads > 0 ? o.threads : experiment_config.numerics.threads;
  if (threads > 0) omp_set_num_threads(threads);

  TrapdoorExperiment experiment(experiment_config);
  RunRecorder recorder(experiment, out, o.quiet, o.stop_after_seconds, o.stop_at_step);
  const ExperimentConfig& c = experiment_config;
  if (resume) {
    Checkpoint ckpt = read_checkpoint(out / "checkpoint.h5");
    const auto metadata = ckpt.metadata;
    const std::int64_t step = ckpt.stats.steps;
    restore_checkpoint(experiment.simulation(), std::move(ckpt));
    experiment.restore(metadata);
    drop_snapshots_after(out / "snapshots.h5", step);
    write_text_atomically(out / "trapdoor.csv", ground_reaction_csv(experiment.ground_reaction()));
    recorder.say(fmt::format("resumed {} at t = {:.6f} s (step {}, stage {})", out.string(),
                             experiment.simulation().time(), step, stage_name(experiment.stage())));
  } else {
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
  record_segment(out, complete, stage_name(experiment.stage()), seconds, sim.step_count() - start_steps,
                 experiment.particle_steps_run(), sim.particles().size());
  return complete ? 0 : 130;
}

}  // namespace trapdem::app
