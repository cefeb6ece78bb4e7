#pragma once
// One progress line for the whole run: stage k of 4, the percent of the whole run's estimated
// work, an ETA for the whole run, and the current stage's own figures. The arithmetic lives here
// as plain functions of numbers (tested without running anything): TrapdoorExperiment measures,
// RunRecorder prints.
//
// Work is counted in particle-steps (particles in the box x steps), what the engine's cost
// follows. The work ahead is the sum over the stages still to run of particles x steps, each
// stage's steps bounded by what the configuration allows: settling by settling.max_time, spin-up
// by spin_up.ramp_time + settling.max_time, lowering exactly travel / (rate dt); the pour by its
// plan (a layer of sites per insertion interval, or the flow rate) until 5 % is poured, then by
// extrapolating the steps it took. A stage that ends early makes the percent jump ahead; the ETA
// (work ahead / the rate measured over a sliding window of wall clock) then drops, and otherwise
// shrinks as the work is done: it does not grow by minutes as a per-stage ETA did.
#include <cstdint>
#include <deque>
#include <string>
#include <utility>

namespace trapdem {

enum class Stage;  // trapdoor_experiment.hpp

// What the progress line says (TrapdoorExperiment fills it, RunRecorder prints progress_line(p)).
struct StageProgress {
  Stage stage{};
  double fraction = 0.0;                 // of the stage, 0..1
  double simulated_time = 0.0;           // s
  double particle_steps_per_second = 0.0;  // over the sliding window; 0 while unknown
  double run_fraction = 0.0;             // of the whole run's estimated work, 0..1
  double seconds_left = -1.0;            // wall clock for the whole run, < 0 while unknown
  std::string detail;                    // what the stage measures (particles poured, energy ratio, ...)
};

// What the configuration lets each stage take (for the work ahead).
struct StagePlan {
  double time_step = 0.0;         // s
  double pour_seconds = 0.0;      // s, the pour's planned duration (0 when starting from a packing)
  double settling_max = 0.0;      // s, settling.max_time
  double spin_up_max = 0.0;       // s, spin_up.ramp_time + settling.max_time
  double travel = 0.0;            // m, trapdoor.travel
  double rate = 0.0;              // m/s, trapdoor.rate
};

// Where the run stands.
struct RunPosition {
  int stage = 0;                  // 0 pour, 1 settling, 2 spin-up, 3 lowering, 4 done
  double particles = 0.0;         // in the box now
  double final_particles = 0.0;   // at the end of the pour (expected; the count now once poured)
  double stage_steps = 0.0;       // steps taken in the current stage
  double stage_time = 0.0;        // s simulated in the current stage
  double pour_fraction = 0.0;     // of the pour, 0..1 (pour only)
  double travel_done = 0.0;       // m (lowering)
};

// Particle-steps still to do from `at` to the end of the run (>= 0).
double work_ahead(const StagePlan& plan, const RunPosition& at);

// The rate of work (particle-steps per wall-clock second) over the last `window` seconds of
// samples (the oldest sample kept is the newest one at least `window` old, so the span is never
// shorter than the window once the run is that old).
class WorkRate {
 public:
  explicit WorkRate(double window_seconds = 60.0) : window_(window_seconds) {}
  void add(double wall_seconds, double work_done);
  bool known() const;              // two samples apart in time and work
  double per_second() const;       // 0 while unknown

 private:
  double window_;
  std::deque<std::pair<double, double>> samples_;  // (wall s, work done)
};

// The whole run's fraction done, never below one reported before (an estimate of the work ahead
// that grows, as a pour past its expected count, holds the percent rather than moving it back).
class RunFraction {
 public:
  double update(double work_done, double work_ahead);

 private:
  double last_ = 0.0;
};

// Text pieces: a duration ("42 s", "3.5 min", "2.0 h"; "estimating" when negative, unknown), a
// fixed-point number that never reads "-0.00" (a value that rounds to zero prints as zero), a
// thread count ("1 thread", "2 threads").
std::string format_duration(double seconds);
std::string fixed_text(double value, int decimals);
std::string threads_text(int threads);

// "stage 2 of 4 (settling)  run  37.2%  left 3.2 min  |  stage  45.0%  t = 0.1234 s  1.23 M
// particle-steps/s  <detail>"; before a rate exists the rate is left out and the ETA says
// "estimating".
std::string progress_line(const StageProgress& p);

}  // namespace trapdem
