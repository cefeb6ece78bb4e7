#include "experiment/run_progress.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "experiment/trapdoor_experiment.hpp"

namespace trapdem {

namespace {

constexpr double kPourMeasuredFrom = 0.05;  // of the pour: from here its steps are extrapolated

}  // namespace

double work_ahead(const StagePlan& plan, const RunPosition& at) {
  const double dt = plan.time_step;
  const double n_final = std::max(at.final_particles, at.particles);
  double work = 0.0;
  if (at.stage <= 0) {
    // The pour: the particle count grows from now to n_final, its mean over the steps left.
    const double planned = plan.pour_seconds / dt;
    const double steps_left = at.pour_fraction >= kPourMeasuredFrom
                                  ? at.stage_steps * (1.0 - at.pour_fraction) / at.pour_fraction
                                  : std::max(0.0, planned - at.stage_steps);
    work += steps_left * 0.5 * (at.particles + n_final);
  }
  // Each later stage from its start, the current one from where it stands; bounded by its longest.
  auto left = [&](int stage, double longest_steps) {
    if (at.stage > stage) return 0.0;
    const double done = at.stage == stage ? at.stage_steps : 0.0;
    return std::max(0.0, longest_steps - done);
  };
  work += n_final * left(1, plan.settling_max / dt);
  work += n_final * left(2, plan.spin_up_max / dt);
  if (at.stage <= 3) {
    const double travel_left = at.stage == 3 ? std::max(0.0, plan.travel - at.travel_done) : plan.travel;
    work += n_final * travel_left / (plan.rate * dt);
  }
  return work;
}

void WorkRate::add(double wall_seconds, double work_done) {
  samples_.emplace_back(wall_seconds, work_done);
  // Drop the oldest while the next one is still at least a window old.
  while (samples_.size() > 2 && wall_seconds - samples_[1].first >= window_) samples_.pop_front();
}

bool WorkRate::known() const {
  return samples_.size() >= 2 && samples_.back().first > samples_.front().first &&
         samples_.back().second > samples_.front().second;
}

double WorkRate::per_second() const {
  if (!known()) return 0.0;
  return (samples_.back().second - samples_.front().second) / (samples_.back().first - samples_.front().first);
}

double RunFraction::update(double work_done, double work_ahead) {
  const double total = work_done + work_ahead;
  const double f = total > 0.0 ? std::clamp(work_done / total, 0.0, 1.0) : 1.0;
  last_ = std::max(last_, f);
  return last_;
}

std::string format_duration(double s) {
  if (s < 0.0 || !std::isfinite(s)) return "estimating";
  if (s < 120.0) return fmt::format("{:.0f} s", s);
  if (s < 7200.0) return fmt::format("{:.1f} min", s / 60.0);
  return fmt::format("{:.1f} h", s / 3600.0);
}

std::string fixed_text(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  // "-0.00": a negative value that rounds to zero (a trapdoor at -1e-12 m) reads as zero.
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

std::string threads_text(int threads) { return fmt::format("{} thread{}", threads, threads == 1 ? "" : "s"); }

std::string progress_line(const StageProgress& p) {
  const int k = std::min(int(p.stage), 3) + 1;
  std::string line = fmt::format("stage {} of 4 {:<12} run {:5.1f}%  left {:<10} | stage {:5.1f}%  t = {:.4f} s",
                                 k, fmt::format("({})", stage_name(p.stage)), 100.0 * p.run_fraction,
                                 format_duration(p.seconds_left), 100.0 * p.fraction, p.simulated_time);
  if (p.particle_steps_per_second > 0.0) line += fmt::format("  {:.2f} M particle-steps/s", p.particle_steps_per_second / 1e6);
  if (!p.detail.empty()) line += "  " + p.detail;
  return line;
}

}  // namespace trapdem
