#include "experiment/trapdoor_experiment.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "experiment/centrifuge_frame.hpp"
#include "experiment/deposit_surface.hpp"
#include "experiment/strongbox.hpp"

namespace trapdem {

namespace {

constexpr std::int64_t kCheckEvery = 500;  // steps between energy checks and load windows

double wall_clock() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string bits(double v) { return fmt::to_string(std::bit_cast<std::uint64_t>(v)); }

}  // namespace

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::pluviation: return "pluviation";
    case Stage::settling: return "settling";
    case Stage::spin_up: return "spin-up";
    case Stage::lowering: return "lowering";
    case Stage::done: return "done";
  }
  return "?";
}

TrapdoorExperiment::TrapdoorExperiment(ExperimentConfig config) : config_(std::move(config)), hopper_(config_) {
  SimulationSettings s;
  s.time_step = config_.time_step();
  s.skin = config_.packing.particles ? config_.skin() : config_.pour_skin();  // the first stage's
  s.domain = strongbox_domain(config_);
  s.max_overlap_fraction = config_.numerics.max_overlap_fraction;
  sim_ = std::make_unique<Simulation>(config_.packing.particles ? *config_.packing.particles : Particles{},
                                      config_.material.particle, s,
                                      config_.packing.bodies ? *config_.packing.bodies : RigidBodies{});
  for (Wall& w : strongbox_walls_for(config_)) sim_->add_wall(std::move(w));
  trapdoor_wall_ = sim_->find_wall(strongbox_walls::trapdoor);
  base_left_wall_ = sim_->find_wall(strongbox_walls::base_left);
  base_right_wall_ = sim_->find_wall(strongbox_walls::base_right);
  const double depth = config_.box.depth, b = config_.trapdoor.width, xc = config_.trapdoor.centre;
  trapdoor_area_ = b * depth;
  base_left_area_ = (xc - 0.5 * b) * depth;
  base_right_area_ = (config_.box.width - xc - 0.5 * b) * depth;
  plan_.time_step = config_.time_step();
  plan_.pour_seconds = config_.packing.particles ? 0.0 : hopper_.planned_duration(config_.expected_particle_count());
  plan_.settling_max = config_.settling.max_time;
  plan_.spin_up_max = config_.spin_up.ramp_time + config_.settling.max_time;
  plan_.travel = config_.trapdoor.travel;
  plan_.rate = config_.trapdoor.rate;
  if (config_.packing.particles) {
    // A packing made elsewhere (ExperimentConfig::from read and checked it) is the simulation's
    // first particles: no pour. On ranks every rank builds it whole; attach_decomposition keeps
    // each rank's share.
    start_stage(config_.packing.start_at_spin_up ? Stage::spin_up : Stage::settling);
  } else {
    start_stage(Stage::pluviation);
  }
}

void TrapdoorExperiment::attach_decomposition(std::unique_ptr<Decomposition> decomposition) {
  if (decomposition && config_.material.shape.is_clump())
    throw InputError(fmt::format("particles.shape.kind = \"{}\": clumps run on one process (a clump's member spheres "
                                 "would cross ranks; docs/ARCHITECTURE.md, \"Clumps\"); run without --ranks",
                                 config_.material.shape.kind));
  decomposition_ = decomposition.get();
  sim_->set_decomposition(std::move(decomposition));
}

// The experiment removes no particle: every one the hopper inserted is in the box, on some rank.
std::size_t TrapdoorExperiment::particle_count() const {
  const std::size_t packed = config_.packing.particles ? config_.packing.particles->size() : 0;
  return decomposition_ ? packed + std::size_t(hopper_.inserted()) : sim_->particles().size();
}

double TrapdoorExperiment::trapdoor_displacement() const { return -sim_->walls()[trapdoor_wall_].displacement.z; }

void TrapdoorExperiment::install_gravity() {
  const double g1 = ExperimentConfig::standard_gravity;
  if (config_.centrifuge.enabled) {
    // The pour and the settling at 1 g on the laboratory floor; from the spin-up on, the
    // centrifuge's rotating frame (centrifuge_frame.hpp) replaces the uniform gravity.
    const bool flying = stage_ != Stage::pluviation && stage_ != Stage::settling;
    sim_->set_gravity(flying ? Vec3{} : Vec3{0, 0, -g1});
    if (flying)
      sim_->set_rotating_frame(centrifuge_frame(config_, stage_start_time_, stage_ == Stage::spin_up));
    else
      sim_->clear_rotating_frame();
  } else {
    install_uniform_gravity();
  }
  if (stage_ == Stage::lowering)
    sim_->set_wall_velocity(trapdoor_wall_, Vec3{0, 0, -config_.trapdoor.rate});
  else
    sim_->set_wall_velocity(trapdoor_wall_, nullptr);
}

void TrapdoorExperiment::install_uniform_gravity() {
  const double g1 = ExperimentConfig::standard_gravity;
  const double gn = config_.spin_up.g_level * g1;
  switch (stage_) {
    case Stage::pluviation:
    case Stage::settling: sim_->set_gravity(Vec3{0, 0, -g1}); break;
    case Stage::spin_up: {
      const double t0 = stage_start_time_, ramp = config_.spin_up.ramp_time;
      // The centrifuge spins up: gravity grows linearly from 1 g to the target over the ramp time.
      sim_->set_gravity([=](double t) {
        const double f = ramp > 0.0 ? std::clamp((t - t0) / ramp, 0.0, 1.0) : 1.0;
        return Vec3{0, 0, -(g1 + (gn - g1) * f)};
      });
      break;
    }
    case Stage::lowering:
    case Stage::done: sim_->set_gravity(Vec3{0, 0, -gn}); break;
  }
}

double TrapdoorExperiment::g_level_now() const {
  if (const RotatingFrame* frame = sim_->rotating_frame()) {  // at the reference level
    const double w = frame->spin(sim_->time()).omega;
    return w * w * config_.centrifuge.radius / ExperimentConfig::standard_gravity;
  }
  return -sim_->gravity().z / ExperimentConfig::standard_gravity;
}

void TrapdoorExperiment::start_stage(Stage stage) {
  stage_ = stage;
  stage_start_time_ = sim_->time();
  spin_up_ramp_done_ = false;
  last_energy_ratio_ = 1.0;
  window_trapdoor_ = window_left_ = window_right_ = 0.0;
  window_steps_ = 0;
  install_gravity();
  install_skin();
}

// The pour's skin while pouring, the run's after; the lists built with the pour's stay exact until
// they are outdated (Simulation::set_skin), so a stage change rebuilds nothing.
void TrapdoorExperiment::install_skin() {
  sim_->set_skin(stage_ == Stage::pluviation ? config_.pour_skin() : config_.skin());
}

bool TrapdoorExperiment::settled(double& ratio) const {
  const double potential = sim_->potential_energy(0.0);
  ratio = potential > 0.0 ? sim_->translational_kinetic_energy() / potential : 0.0;
  return ratio < config_.settling.energy_ratio;
}

BaseLoad TrapdoorExperiment::wall_load(std::size_t wall, double area, double reference_stress) const {
  const double window = std::max<std::int64_t>(window_steps_, 1);
  const double sum = wall == trapdoor_wall_ ? window_trapdoor_ : (wall == base_left_wall_ ? window_left_ : window_right_);
  BaseLoad load;
  load.force = sum / window;
  load.stress = load.force / area;
  load.ratio = reference_stress > 0.0 ? load.stress / reference_stress : 0.0;
  return load;
}

void TrapdoorExperiment::begin_lowering(ExperimentObserver& observer) {
  geostatic_trapdoor_ = wall_load(trapdoor_wall_, trapdoor_area_, 0.0).stress;
  geostatic_left_ = wall_load(base_left_wall_, base_left_area_, 0.0).stress;
  geostatic_right_ = wall_load(base_right_wall_, base_right_area_, 0.0).stress;
  GroundReactionRow first;
  first.time = sim_->time();
  first.trapdoor = wall_load(trapdoor_wall_, trapdoor_area_, geostatic_trapdoor_);
  first.geostatic_stress = geostatic_trapdoor_;
  first.base_left = wall_load(base_left_wall_, base_left_area_, geostatic_left_);
  first.base_right = wall_load(base_right_wall_, base_right_area_, geostatic_right_);
  rows_ = {first};
  next_row_ = 1;
  next_snapshot_ = 0;
  start_stage(Stage::lowering);
  observer.ground_reaction_row(first, rows_);
}

bool TrapdoorExperiment::run(ExperimentObserver& observer) {
  // A run from a packing records it as its first snapshot ("packing"), as a pour's end is one.
  if (config_.packing.particles && sim_->step_count() == 0) observer.snapshot_due("packing");
  report(observer, true);
  while (stage_ != Stage::done) {
    if (observer.stop_requested()) {
      observer.checkpoint(state());
      return false;
    }
    if (observer.checkpoint_due()) observer.checkpoint(state());
    advance(observer);
    const double particles = double(particle_count());  // those of the step just taken
    particle_steps_run_ += particles;
    particle_steps_total_ += particles;
    if (sim_->step_count() % 200 == 0 && stage_ != Stage::done) report(observer, false);
  }
  return true;  // the last stage's summary was its stage_finished: no progress line after it
}

bool TrapdoorExperiment::advance(ExperimentObserver& observer) {
  const double t = sim_->time() - stage_start_time_;
  switch (stage_) {
    case Stage::pluviation: {
      hopper_.pour(*sim_, decomposition_);
      sim_->step();
      if (hopper_.finished(*sim_)) {
        std::string notes;
        if (hopper_.flow_limited_by_band()) notes += "; the flow rate asked for exceeded what the hopper band passes";
        if (hopper_.box_full())
          notes += fmt::format("; the box is full: the deposit reached the hopper band's ceiling ({:.1f} mm) with {} "
                               "{}, and the pour ends there",
                               hopper_.band_ceiling() * 1e3, hopper_.inserted(),
                               config_.pluviation.count > 0
                                   ? fmt::format("of the {} particles asked for poured", config_.pluviation.count)
                                   : fmt::format("particles poured, before the nominal surface reached the fill "
                                                 "height ({:.1f} mm)",
                                                 config_.pluviation.fill_height * 1e3));
        observer.stage_finished(stage_, fmt::format("{} particles poured ({:.4g} kg), nominal surface {:.1f} mm (the "
                                                    "mass at solid fraction {:g}; the deposit's is measured when it "
                                                    "has settled){}",
                                                    hopper_.inserted(), hopper_.inserted_mass(),
                                                    hopper_.surface_height() * 1e3,
                                                    config_.pluviation.packing_fraction, notes));
        observer.snapshot_due(stage_name(stage_));
        start_stage(Stage::settling);
      }
      return true;
    }
    case Stage::settling: {
      sim_->step();
      if (sim_->step_count() % kCheckEvery != 0) return true;
      const bool calm = settled(last_energy_ratio_);
      if ((calm && t >= config_.settling.min_time) || t >= config_.settling.max_time) {
        observer.stage_finished(
            stage_, fmt::format("kinetic/potential energy {:.3g} after {:.4g} s{}; {}", last_energy_ratio_, t,
                                calm ? "" : " (max_time reached before the energy criterion)",
                                deposit_surface_text(measure_deposit_surface(*sim_, config_, decomposition_), config_)));
        observer.snapshot_due(stage_name(stage_));
        start_stage(Stage::spin_up);
      }
      return true;
    }
    case Stage::spin_up: {
      sim_->step();
      window_trapdoor_ -= sim_->walls()[trapdoor_wall_].force.z;
      window_left_ -= sim_->walls()[base_left_wall_].force.z;
      window_right_ -= sim_->walls()[base_right_wall_].force.z;
      ++window_steps_;
      if (!spin_up_ramp_done_ && t >= config_.spin_up.ramp_time) spin_up_ramp_done_ = true;
      if (sim_->step_count() % kCheckEvery != 0) return true;
      const bool calm = settled(last_energy_ratio_);
      const double since_ramp = t - config_.spin_up.ramp_time;
      if (spin_up_ramp_done_ &&
          ((calm && since_ramp >= config_.settling.min_time) || since_ramp >= config_.settling.max_time)) {
        observer.stage_finished(stage_, fmt::format("{:.4g} g reached; kinetic/potential energy {:.3g}{}",
                                                    config_.spin_up.g_level, last_energy_ratio_,
                                                    calm ? "" : " (max_time reached before the energy criterion)"));
        const auto& targets = config_.output.snapshot_displacements;
        if (targets.empty() || targets.front() > 0.0) observer.snapshot_due(stage_name(stage_));
        begin_lowering(observer);
        return true;
      }
      window_trapdoor_ = window_left_ = window_right_ = 0.0;  // the reference is the last window's mean
      window_steps_ = 0;
      return true;
    }
    case Stage::lowering: {
      const auto& targets = config_.output.snapshot_displacements;
      const double eps = 1e-12;
      while (next_snapshot_ < targets.size() && trapdoor_displacement() >= targets[next_snapshot_] - eps) {
        observer.snapshot_due(stage_name(stage_));
        ++next_snapshot_;
      }
      sim_->step();
      window_trapdoor_ -= sim_->walls()[trapdoor_wall_].force.z;
      window_left_ -= sim_->walls()[base_left_wall_].force.z;
      window_right_ -= sim_->walls()[base_right_wall_].force.z;
      ++window_steps_;
      const double s = trapdoor_displacement();
      const bool finished = s >= config_.trapdoor.travel - eps;
      if (s >= next_row_ * config_.output.ground_reaction_step - eps || finished) {
        GroundReactionRow row;
        row.time = sim_->time();
        row.trapdoor_displacement = s;
        row.trapdoor = wall_load(trapdoor_wall_, trapdoor_area_, geostatic_trapdoor_);
        row.geostatic_stress = geostatic_trapdoor_;
        row.base_left = wall_load(base_left_wall_, base_left_area_, geostatic_left_);
        row.base_right = wall_load(base_right_wall_, base_right_area_, geostatic_right_);
        rows_.push_back(row);
        observer.ground_reaction_row(row, rows_);
        window_trapdoor_ = window_left_ = window_right_ = 0.0;
        window_steps_ = 0;
        while (next_row_ * config_.output.ground_reaction_step <= s + eps) ++next_row_;
      }
      if (finished) {
        while (next_snapshot_ < targets.size() && s >= targets[next_snapshot_] - eps) ++next_snapshot_;
        observer.snapshot_due(stage_name(stage_));
        const GroundReactionRow& last = rows_.back();
        observer.stage_finished(stage_, fmt::format("trapdoor lowered {} mm; trapdoor stress {:.4g} Pa = {:.3f} of "
                                                    "the {:.4g} Pa before lowering",
                                                    fixed_text(s * 1e3, 2), last.trapdoor.stress, last.trapdoor.ratio,
                                                    geostatic_trapdoor_));
        stage_ = Stage::done;
        install_gravity();
      }
      return true;
    }
    case Stage::done: return false;
  }
  return false;
}

void TrapdoorExperiment::report(ExperimentObserver& observer, bool force) {
  const double now = wall_clock();
  if (!force && now - last_report_clock_ < config_.output.log_interval) return;
  last_report_clock_ = now;
  StageProgress p;
  p.stage = stage_;
  p.simulated_time = sim_->time();
  const double t = sim_->time() - stage_start_time_;
  auto energy_fraction = [&] {
    const double target = config_.settling.energy_ratio;
    if (last_energy_ratio_ <= target) return 1.0;
    return std::clamp(std::log(1.0 / last_energy_ratio_) / std::log(1.0 / target), 0.0, 0.99);
  };
  switch (stage_) {
    case Stage::pluviation: {
      // The pour's own end rule: the count, or the surface estimated from the mass at the fill height.
      const double expected = double(std::max<std::int64_t>(config_.expected_particle_count(), 1));
      p.fraction = std::min(1.0, config_.pluviation.count > 0 ? double(hopper_.inserted()) / expected
                                                               : hopper_.surface_height() / config_.pluviation.fill_height);
      p.detail = fmt::format("{} particles poured, surface about {:.1f} mm", hopper_.inserted(),
                             hopper_.surface_height() * 1e3);
      break;
    }
    case Stage::settling:
      p.fraction = energy_fraction();
      p.detail = fmt::format("kinetic/potential energy {:.2e} (target {:.1e})", last_energy_ratio_,
                             config_.settling.energy_ratio);
      break;
    case Stage::spin_up: {
      const double ramp = config_.spin_up.ramp_time;
      const double g = g_level_now();
      p.fraction = spin_up_ramp_done_ ? 0.5 + 0.5 * energy_fraction() : (ramp > 0.0 ? 0.5 * std::min(1.0, t / ramp) : 0.5);
      p.detail = fmt::format("gravity {:.1f} g, kinetic/potential energy {:.2e}", g, last_energy_ratio_);
      break;
    }
    case Stage::lowering:
    case Stage::done:
      p.fraction = std::min(1.0, trapdoor_displacement() / config_.trapdoor.travel);
      p.detail = fmt::format("trapdoor at {} mm, stress ratio {:.3f}", fixed_text(trapdoor_displacement() * 1e3, 2),
                             rows_.empty() ? 1.0 : rows_.back().trapdoor.ratio);
      break;
  }
  // The whole run: its work done against the work ahead (run_progress.hpp), and the rate over a
  // sliding window of wall clock.
  RunPosition at;
  at.stage = int(stage_);
  at.particles = double(particle_count());
  at.final_particles = stage_ == Stage::pluviation
                           ? std::max(double(config_.expected_particle_count()), at.particles)
                           : at.particles;
  at.stage_time = t;
  at.stage_steps = t / sim_->time_step();
  at.pour_fraction = stage_ == Stage::pluviation ? p.fraction : 1.0;
  at.travel_done = stage_ == Stage::lowering ? trapdoor_displacement() : 0.0;
  const double ahead = work_ahead(plan_, at);
  rate_.add(now, particle_steps_total_);
  p.run_fraction = run_fraction_.update(particle_steps_total_, ahead);
  p.particle_steps_per_second = rate_.per_second();
  p.seconds_left = rate_.known() ? ahead / p.particle_steps_per_second : -1.0;
  observer.progress(p);
}

std::map<std::string, std::string> TrapdoorExperiment::state() const {
  std::map<std::string, std::string> s = hopper_.state();
  s["experiment.stage"] = fmt::to_string(int(stage_));
  s["experiment.stage_start_time"] = bits(stage_start_time_);
  s["experiment.spin_up_ramp_done"] = fmt::to_string(int(spin_up_ramp_done_));
  s["experiment.last_energy_ratio"] = bits(last_energy_ratio_);
  s["experiment.window_trapdoor"] = bits(window_trapdoor_);
  s["experiment.window_left"] = bits(window_left_);
  s["experiment.window_right"] = bits(window_right_);
  s["experiment.window_steps"] = fmt::to_string(window_steps_);
  s["experiment.geostatic_trapdoor"] = bits(geostatic_trapdoor_);
  s["experiment.geostatic_left"] = bits(geostatic_left_);
  s["experiment.geostatic_right"] = bits(geostatic_right_);
  s["experiment.next_snapshot"] = fmt::to_string(next_snapshot_);
  s["experiment.next_row"] = fmt::to_string(next_row_);
  s["experiment.ground_reaction_csv"] = ground_reaction_csv(rows_);
  s["experiment.particle_steps_total"] = bits(particle_steps_total_);
  return s;
}

void TrapdoorExperiment::restore(const std::map<std::string, std::string>& s) {
  auto get = [&](const std::string& key) -> const std::string& {
    auto it = s.find(key);
    if (it == s.end()) throw InputError(fmt::format("checkpoint: missing experiment state '{}'", key));
    return it->second;
  };
  auto dbl = [&](const std::string& key) { return std::bit_cast<double>(std::stoull(get(key))); };
  hopper_.restore(s);
  const int stage = std::stoi(get("experiment.stage"));
  if (stage < 0 || stage > int(Stage::done)) throw InputError("checkpoint: unknown experiment stage");
  stage_ = Stage(stage);
  stage_start_time_ = dbl("experiment.stage_start_time");
  spin_up_ramp_done_ = get("experiment.spin_up_ramp_done") == "1";
  last_energy_ratio_ = dbl("experiment.last_energy_ratio");
  window_trapdoor_ = dbl("experiment.window_trapdoor");
  window_left_ = dbl("experiment.window_left");
  window_right_ = dbl("experiment.window_right");
  window_steps_ = std::stoll(get("experiment.window_steps"));
  geostatic_trapdoor_ = dbl("experiment.geostatic_trapdoor");
  geostatic_left_ = dbl("experiment.geostatic_left");
  geostatic_right_ = dbl("experiment.geostatic_right");
  next_snapshot_ = std::stoul(get("experiment.next_snapshot"));
  next_row_ = std::stoll(get("experiment.next_row"));
  rows_ = parse_ground_reaction_csv(get("experiment.ground_reaction_csv"), "checkpoint ground reaction");
  // Checkpoints of an earlier version do not have it: the progress then counts from the resume.
  if (const auto it = s.find("experiment.particle_steps_total"); it != s.end()) particle_steps_total_ = dbl(it->first);
  install_gravity();
  install_skin();
}

}  // namespace trapdem
