#pragma once
// The trapdoor experiment's stages (the seed paper's sections 2 and 4.3): pluviation at 1 g,
// settling, spin-up to the centrifuge's g level, and the trapdoor lowered at a constant rate.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/ground_reaction.hpp"
#include "experiment/pluviation.hpp"
#include "experiment/run_progress.hpp"

namespace trapdem {

enum class Stage { pluviation = 0, settling = 1, spin_up = 2, lowering = 3, done = 4 };
const char* stage_name(Stage stage);

// What the runner does with the experiment's events: log, write files, checkpoint, stop.
class ExperimentObserver {
 public:
  virtual ~ExperimentObserver() = default;
  virtual void progress(const StageProgress&) {}
  virtual void stage_finished(Stage, const std::string& summary) {}
  virtual void snapshot_due(const std::string& stage_label) {}
  virtual void ground_reaction_row(const GroundReactionRow&, const std::vector<GroundReactionRow>& all) {}
  virtual bool checkpoint_due() { return false; }  // asked between steps: a wall-clock interval passed
  virtual void checkpoint(const std::map<std::string, std::string>& experiment_state) {}
  virtual bool stop_requested() { return false; }  // SIGINT/SIGTERM: checkpoint, then return from run()
};

class TrapdoorExperiment {
 public:
  explicit TrapdoorExperiment(ExperimentConfig config);

  // Runs from the current state to the end, or until the observer asks to stop (then it
  // checkpoints first). Returns true when the experiment is complete.
  bool run(ExperimentObserver& observer);

  // Runs the experiment as one rank of a decomposition (every rank builds the same experiment,
  // then attaches its rank's decomposition before the first step; from then on run() and the
  // stages are collective). Without one, one process as always.
  void attach_decomposition(std::unique_ptr<Decomposition> decomposition);
  // The particles in the box (on ranks: every rank's, the pour's count).
  std::size_t particle_count() const;

  Simulation& simulation() { return *sim_; }
  const Simulation& simulation() const { return *sim_; }
  // Particle-steps (particles in the box, summed over steps) taken by run() calls of this object:
  // the work behind a run's particle-steps per second while the count grows during pluviation.
  double particle_steps_run() const { return particle_steps_run_; }
  // The same since the run's first step (kept in checkpoints): the work done, for the progress line.
  double particle_steps_total() const { return particle_steps_total_; }
  const ExperimentConfig& config() const { return config_; }
  Stage stage() const { return stage_; }
  double trapdoor_displacement() const;  // m, downward positive
  const std::vector<GroundReactionRow>& ground_reaction() const { return rows_; }

  // The experiment's own state beyond the engine's, for checkpoint metadata, and its restoration
  // after the engine has been restored from the same checkpoint.
  std::map<std::string, std::string> state() const;
  void restore(const std::map<std::string, std::string>& state);

 private:
  void start_stage(Stage stage);
  bool advance(ExperimentObserver& observer);   // one step and the stage logic; false when done
  bool settled(double& energy_ratio) const;
  void begin_lowering(ExperimentObserver& observer);
  // The body force of the stage: uniform gravity, or from the spin-up on the centrifuge's
  // rotating frame when [centrifuge] is on; and the trapdoor's motion.
  void install_gravity();
  void install_uniform_gravity();  // 1 g, the linear ramp to N g, N g (the frame off)
  double g_level_now() const;      // g, at the reference level in the frame
  void install_skin();             // the stage's Verlet skin (the pour has its own)
  BaseLoad wall_load(std::size_t wall, double area, double reference_stress) const;
  void report(ExperimentObserver& observer, bool force);

  ExperimentConfig config_;
  std::unique_ptr<Simulation> sim_;
  Decomposition* decomposition_ = nullptr;  // the simulation's, when it runs on ranks
  Hopper hopper_;
  Stage stage_ = Stage::pluviation;
  double stage_start_time_ = 0.0;      // s, simulated
  bool spin_up_ramp_done_ = false;
  double last_energy_ratio_ = 1.0;
  std::size_t trapdoor_wall_ = 0, base_left_wall_ = 0, base_right_wall_ = 0;
  double trapdoor_area_ = 0.0, base_left_area_ = 0.0, base_right_area_ = 0.0;  // m^2
  // Loads averaged over a window of steps (they fluctuate step to step).
  double window_trapdoor_ = 0.0, window_left_ = 0.0, window_right_ = 0.0;
  std::int64_t window_steps_ = 0;
  double geostatic_trapdoor_ = 0.0, geostatic_left_ = 0.0, geostatic_right_ = 0.0;  // Pa
  std::size_t next_snapshot_ = 0;      // index into output.snapshot_displacements
  std::int64_t next_row_ = 0;          // next ground-reaction row at next_row_ * ground_reaction_step
  std::vector<GroundReactionRow> rows_;
  double particle_steps_total_ = 0.0;   // since the run's first step (state)
  // Wall-clock bookkeeping for progress lines (not part of the state).
  double last_report_clock_ = -1e300;
  double particle_steps_run_ = 0.0;
  StagePlan plan_;
  WorkRate rate_;
  RunFraction run_fraction_;
};

}  // namespace trapdem
