#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"

// The engine's diagnostics: energies and contact counts (deterministic serial sums), and the
// checks that stop a failing run with a message naming the particle, the step and the likely cause.

namespace trapdem {

std::string Simulation::describe_particle(std::uint32_t i) const {
  const Particles& p = state_.particles;
  const Vec3& x = p.position[i];
  const Vec3& v = p.velocity[i];
  return fmt::format("particle id {} (radius {:.4g} m) at ({:.6g}, {:.6g}, {:.6g}) m moving at ({:.4g}, {:.4g}, {:.4g}) m/s",
                     p.id[i], p.radius[i], x.x, x.y, x.z, v.x, v.y, v.z);
}

void Simulation::check_stability() const {
  const Particles& p = state_.particles;
  if (bad_particle_ < 0 && escaped_particle_ < 0 && !(max_overlap_seen_ > settings_.max_overlap_fraction)) return;
  // Only a failing run gets here: the message costs a scan of the masses and a string.
  const std::string when = fmt::format("step {} (t = {:.6g} s, dt = {:.4g} s, critical step {:.4g} s)", stats_.steps,
                                       time_, dt_, critical_time_step());
  if (bad_particle_ >= 0)
    throw SimulationError(fmt::format(
        "unstable run at {}: {} has a non-finite velocity (NaN or Inf). Likely cause: the time step is too large for "
        "the stiffness, or an input value is not a number.",
        when, describe_particle(static_cast<std::uint32_t>(bad_particle_))));
  if (escaped_particle_ >= 0) {
    const Domain& d = settings_.domain;
    throw SimulationError(fmt::format(
        "particle left the domain at {}: {} is outside [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m. Likely "
        "cause: a missing or too soft wall (it passed through), or an unstable time step.",
        when, describe_particle(static_cast<std::uint32_t>(escaped_particle_)), d.lower.x, d.upper.x, d.lower.y,
        d.upper.y, d.lower.z, d.upper.z));
  }
  if (max_overlap_seen_ > settings_.max_overlap_fraction) {
    // Find the worst contact again (only on failure) to name it and the stiffness that governs it:
    // the particle law's for a pair, the wall's own law for a particle-wall contact.
    std::string where = "a particle-wall contact";
    std::string stiffness_of = "particle";
    const ContactLaw* governing = &law_;
    double worst = 0.0;
    const Domain& dom = settings_.domain;
    for (std::uint32_t i = 0; i + 1 < state_.lists.pairs.first.size(); ++i) {
      for (std::uint32_t k = state_.lists.pairs.first[i]; k < state_.lists.pairs.first[i + 1]; ++k) {
        const std::uint32_t j = state_.lists.pairs.partner[k];
        const double ov = p.radius[i] + p.radius[j] - norm(dom.minimum_image(p.position[i] - p.position[j]));
        const double frac = ov / std::min(p.radius[i], p.radius[j]);
        if (frac > worst) {
          worst = frac;
          where = fmt::format("the contact of particle ids {} and {}", p.id[i], p.id[j]);
        }
      }
    }
    for (std::uint32_t i = 0; i + 1 < state_.lists.walls.first.size(); ++i) {
      for (std::uint32_t k = state_.lists.walls.first[i]; k < state_.lists.walls.first[i + 1]; ++k) {
        const Wall& w = state_.walls[state_.lists.walls.wall[k]];
        const double frac = (p.radius[i] - wall_proximity(w, p.position[i]).distance) / p.radius[i];
        if (frac > worst) {
          worst = frac;
          where = fmt::format("the contact of particle id {} with wall '{}'", p.id[i], w.name);
          stiffness_of = fmt::format("wall '{}'", w.name);
          governing = &w.law;
        }
      }
    }
    // Above the central-difference limit 2 sqrt(m/k) the integration itself is unstable: advising a
    // stiffer contact would make it worse.
    const double limit = 2.0 * critical_time_step();
    std::vector<const ContactLaw*> wall_laws;
    for (const Wall& w : state_.walls) wall_laws.push_back(&w.law);
    const std::string cause =
        dt_ > limit
            ? fmt::format("the time step ({:.4g} s) exceeds the stability limit 2 {} = {:.4g} s: "
                          "lower settings.time_step (or time_step_fraction; 0.1-0.2 is usual)",
                          dt_, critical_time_step_formula(law_, wall_laws), limit)
            : fmt::format("the {} is too low for the load (raise it, or lower gravity), or the time step is too large",
                          describe_stiffness(*governing, stiffness_of));
    throw SimulationError(fmt::format(
        "overlap blow-up at {}: {} overlaps by {:.1f}% of the smaller radius (limit {:.1f}%). Likely cause: {}.", when,
        where, 100.0 * max_overlap_seen_, 100.0 * settings_.max_overlap_fraction, cause));
  }
}

double Simulation::translational_kinetic_energy() const {
  double e = 0.0;
  const RigidBodies& bodies = state_.bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b) e += 0.5 * bodies.mass[b] * norm2(bodies.velocity[b]);
  if (!bodies.empty()) return e;
  const Particles& p = state_.particles;
  for (std::size_t i = 0; i < owned_count(); ++i) e += 0.5 * p.mass[i] * norm2(p.velocity[i]);
  return global_sum(e);
}

double Simulation::rotational_kinetic_energy() const {
  double e = 0.0;
  const RigidBodies& bodies = state_.bodies;  // L . w / 2
  for (std::size_t b = 0; b < bodies.size(); ++b) e += 0.5 * dot(bodies.angular_momentum[b], bodies.angular_velocity(b));
  if (!bodies.empty()) return e;
  const Particles& p = state_.particles;
  for (std::size_t i = 0; i < owned_count(); ++i) e += 0.5 / p.inv_inertia[i] * norm2(p.angular_velocity[i]);
  return global_sum(e);
}

double Simulation::potential_energy(double reference_height) const {
  const Particles& p = state_.particles;
  const Vec3 g = gravity();
  const double g_len = norm(g);
  double e = 0.0;
  const RigidBodies& bodies = state_.bodies;
  if (g_len > 0.0) {
    const Vec3 up = -g / g_len;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      e += bodies.mass[b] * g_len * (dot(bodies.position[b], up) - reference_height);
    for (std::size_t i = 0; bodies.empty() && i < owned_count(); ++i)
      e += p.mass[i] * g_len * (dot(p.position[i], up) - reference_height);
  }
  if (frame_) {
    const Vec3 level{frame_->axis_point.x, frame_->axis_point.y, reference_height};
    const double reference_radius = norm(frame_->radius_vector(level));
    if (bodies.empty()) {
      e += frame_potential_energy(p, owned_count(), *frame_, time_, reference_radius);
    } else {  // of the centres of mass (the frame's torque about them is not modelled: body_motion.hpp)
      const FrameSpin s = frame_->spin ? frame_->spin(time_) : FrameSpin{};
      for (std::size_t b = 0; b < bodies.size(); ++b)
        e += 0.5 * bodies.mass[b] * s.omega * s.omega *
             (reference_radius * reference_radius - norm2(frame_->radius_vector(bodies.position[b])));
    }
  }
  return global_sum(e);
}

double Simulation::total_mass() const {
  const RigidBodies& bodies = state_.bodies;
  if (!bodies.empty()) return std::accumulate(bodies.mass.begin(), bodies.mass.end(), 0.0);
  double m = 0.0;
  for (std::size_t i = 0; i < owned_count(); ++i) m += state_.particles.mass[i];
  return global_sum(m);
}

std::size_t Simulation::contact_count() const {
  std::size_t c = 0;
  for (std::uint32_t slot : state_.lists.pair_contact) c += slot != kNoContact ? 1 : 0;
  return decomposition_ ? std::size_t(std::llround(global_sum(double(c)))) : c;
}

}  // namespace trapdem
