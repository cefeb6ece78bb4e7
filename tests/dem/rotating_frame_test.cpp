// The rotating frame (rotating_frame.hpp) against closed forms: a particle at rest in the frame
// feels omega^2 r away from the axis at its own radius (the direction fans out across the width)
// plus the Euler force of a spin-up; a free particle's path over a drop (centrifugal and Coriolis
// together) against the exact straight line of the inertial frame; the energy of a frictionless
// elastic bed in the frame (kinetic + centrifugal potential + elastic) conserved; and no frame,
// no change.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "dem/rotating_frame.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

namespace trapdem {
namespace {

using testing_support::box;
using testing_support::frictionless_law;
using testing_support::report;

// The seed's facility: 3.0 m radius, 50 g there.
constexpr double kRadius = 3.0;                 // m
constexpr double kG = 9.81;                     // m/s^2
const double kOmega = std::sqrt(50.0 * kG / kRadius);  // rad/s

// A centrifuge frame in model coordinates (z up, the axis above the model along -y, so that +x is
// the direction of travel): the axis passes through (0, 0, kRadius).
RotatingFrame centrifuge_frame(double omega, double alpha = 0.0, bool coriolis = true, bool euler = true) {
  RotatingFrame f;
  f.axis_point = {0.0, 0.0, kRadius};
  f.axis = {0.0, -1.0, 0.0};
  f.coriolis = coriolis;
  f.euler = euler;
  f.spin = [omega, alpha](double) { return FrameSpin{omega, alpha}; };
  return f;
}

Particles scattered_particles(const std::vector<Vec3>& at) {
  Particles p;
  for (std::size_t i = 0; i < at.size(); ++i) p.add(std::int64_t(i), at[i], 0.001, 2500.0, {});
  return p;
}

SimulationSettings far_apart_settings(double half, double dt) {
  SimulationSettings s;
  s.domain = box(half);
  s.domain.upper.z = kRadius - 0.01;  // below the axis
  s.time_step = dt;
  s.skin = 0.001;
  return s;
}

// At rest in the frame, over one step of dt the velocity becomes a dt with a = omega^2 r_perp -
// alpha k x r: the particle's own radius (the base sees more than the surface) and direction
// (at x = 0.16 m, a side wall of the seed's box, tilted by atan(0.16 / r) ~ 3 degrees). The
// tolerance 1e-4 relative: within the step the Coriolis term turns the velocity by 2 omega dt/2
// = 1.3e-5 rad at dt = 1e-6 s, and the position moves by a dt^2 (1e-10 of r): both well below it.
TEST(RotatingFrame, ParticleAtRestFeelsCentrifugalAtItsRadiusAndDirection) {
  const std::vector<Vec3> at = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.36}, {0.16, 0.0, 0.0}, {-0.16, 0.005, 0.12}};
  for (const double alpha : {0.0, 2.0}) {
    const double dt = 1e-6;
    Simulation sim(scattered_particles(at), frictionless_law(1e4, 1.0), far_apart_settings(0.5, dt));
    sim.set_gravity(Vec3{});
    sim.set_rotating_frame(centrifuge_frame(kOmega, alpha));
    sim.step();
    for (std::size_t i = 0; i < at.size(); ++i) {
      const std::size_t k = std::size_t(sim.particles().id[i]);
      const Vec3 r{at[k].x, 0.0, at[k].z - kRadius};  // from the axis, normal to it
      const Vec3 axis{0, -1, 0};
      const Vec3 expected = kOmega * kOmega * r - alpha * cross(axis, r);
      const Vec3 measured = sim.particles().velocity[i] / dt;
      const double error = norm(measured - expected) / norm(expected);
      report("at ({}, {}) m, alpha {}: |a| = {:.4f} m/s^2 (omega^2 r = {:.4f}), relative error {:.1e} (tol 1e-4)",
             at[k].x, at[k].z, alpha, norm(measured), kOmega * kOmega * norm(r), error);
      EXPECT_LT(error, 1e-4) << "particle at " << at[k].x << ", " << at[k].z;
    }
    // The base is farther from the axis than the surface 0.36 m above it: (3.0 / 2.64) more.
    const auto find = [&](std::int64_t id) {
      for (std::size_t i = 0; i < sim.particles().size(); ++i)
        if (sim.particles().id[i] == id) return i;
      return std::size_t(0);
    };
    EXPECT_NEAR(norm(sim.particles().velocity[find(0)]) / norm(sim.particles().velocity[find(1)]), 3.0 / 2.64,
                alpha == 0.0 ? 1e-4 : 1e-2);
    // The side particle's acceleration leans outwards across the width by atan(0.16 / 3.0).
    const Vec3 side = sim.particles().velocity[find(2)];
    if (alpha == 0.0) {
      EXPECT_NEAR(std::atan2(side.x, -side.z), std::atan2(0.16, 3.0), 1e-4);
    }
  }
}

// A free particle released at rest in the frame at radius r0 moves, seen from the ground, on a
// straight line at the speed omega r0 of its release point; in the frame (rotated back by
// omega t) its radial and along-travel coordinates are r0 (cos wt + wt sin wt) and
// r0 (wt cos wt - sin wt): it lags behind the rotation by r0 (wt)^3 / 3 for small wt. Over a drop
// of 0.3 m from the surface of a 0.36 m model at 3 m and 50 g that lag is ~0.08 m. The scheme is
// second order: the error is ~(omega dt)^2 r0 per unit of (omega t)^2, 1e-8 m at dt = 1e-5 s; the
// tolerance 1e-6 m is 1e-5 of the lag, and halving dt must cut the error by ~4. Without the
// Coriolis term the particle would fall along its radius: the lag, and the test, would fail by 0.08 m.
TEST(RotatingFrame, FreeParticleDropMatchesTheInertialStraightLine) {
  const double r0 = kRadius - 0.36, drop = 0.3;
  const double turn_end = std::sqrt(std::pow((r0 + drop) / r0, 2) - 1.0);  // omega t when r = r0 + drop
  auto run = [&](double dt, bool coriolis) {
    Simulation sim(scattered_particles({{0.0, 0.0, 0.36}}), frictionless_law(1e4, 1.0), far_apart_settings(0.5, dt));
    sim.set_gravity(Vec3{});
    sim.set_rotating_frame(centrifuge_frame(kOmega, 0.0, coriolis));
    const std::int64_t steps = std::llround(turn_end / kOmega / dt);
    sim.run(steps);
    const double wt = kOmega * sim.time();
    const Vec3 exact{r0 * (wt * std::cos(wt) - std::sin(wt)), 0.0, kRadius - r0 * (std::cos(wt) + wt * std::sin(wt))};
    return std::pair{sim.particles().position[0], exact};
  };
  const auto [coarse, exact_coarse] = run(2e-5, true);
  const auto [fine, exact_fine] = run(1e-5, true);
  const double error_coarse = norm(coarse - exact_coarse), error_fine = norm(fine - exact_fine);
  report("drop {} m: lag {:.4f} m, error {:.2e} m at dt 2e-5, {:.2e} m at dt 1e-5 (ratio {:.2f}, tol 1e-6 m)", drop,
         -exact_fine.x, error_coarse, error_fine, error_coarse / error_fine);
  EXPECT_GT(-exact_fine.x, 0.05);  // the closed form lags by several centimetres: a real check
  EXPECT_LT(error_fine, 1e-6);
  EXPECT_NEAR(error_coarse / error_fine, 4.0, 0.5);  // second order
  EXPECT_NEAR(fine.z, exact_fine.z, 1e-6);
  const auto [radial_only, exact] = run(1e-5, false);
  EXPECT_NEAR(radial_only.x, 0.0, 1e-12);  // no Coriolis term: no lag
  EXPECT_GT(std::fabs(radial_only.x - exact.x), 0.05);
}

// A frictionless elastic bed (e = 1, mu = 0, no rolling; nothing dissipates, so it never comes to
// rest) dropped from a loose lattice onto the floor of a box of walls in the frame, at constant omega: kinetic + elastic (pairs and walls,
// k_n delta^2 / 2) + centrifugal potential (-m omega^2 r^2 / 2) is conserved; the Coriolis force
// does no work. The error is that of velocity Verlet for the springs (each contact's onset and end
// inside a step, and the oscillation (w_c dt)^2 of each sustained contact's energy): measured at
// 1e-4 of the potential energy released by the fall at this dt, tolerance 1e-3 of it. A
// centrifugal kick evaluated at one radius for all (a uniform field) would miss the balance by the
// field's change over the fall, ~5 % here.
TEST(RotatingFrame, ElasticBedConservesEnergyInTheFrame) {
  const double r = 0.001, half = 0.006;
  ContactLaw law = frictionless_law(1e4, 1.0);
  Particles p;
  std::int64_t id = 0;
  testing_support::Rng rng(5);
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i)
        p.add(id++, {-half + 0.0015 + 0.003 * i + rng.uniform(-2e-4, 2e-4), -0.0015 + 0.003 * j, 0.0015 + 0.0032 * k},
              r, 2500.0, {});
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.01, 0.01, 0.05};
  s.time_step_fraction = 0.02;
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{});
  // A 0.2 m radius frame at 50 g there: a strong gradient (r changes by 10 % over the bed).
  const double radius = 0.2, omega = std::sqrt(50.0 * kG / radius);
  RotatingFrame f;
  f.axis_point = {0.0, 0.0, radius};
  f.axis = {0.0, -1.0, 0.0};
  f.spin = [omega](double) { return FrameSpin{omega, 0.0}; };
  sim.set_rotating_frame(f);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("x-", {-half, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {half, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, -0.003, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, 0.003, 0}, {0, -1, 0}, law));
  const auto energy = [&] {
    const Particles& q = sim.particles();
    double e = sim.kinetic_energy() + sim.potential_energy(0.0);
    for (std::size_t i = 0; i < q.size(); ++i) {
      for (std::size_t j = i + 1; j < q.size(); ++j) {
        const double overlap = q.radius[i] + q.radius[j] - norm(q.position[i] - q.position[j]);
        if (overlap > 0.0) e += 0.5 * law.normal_stiffness * overlap * overlap;
      }
      for (const Wall& w : sim.walls()) {
        const double overlap = q.radius[i] - dot(q.position[i] - w.origin, w.normal);
        if (overlap > 0.0) e += 0.5 * law.normal_stiffness * overlap * overlap;
      }
    }
    return e;
  };
  const double e0 = energy(), u0 = sim.potential_energy(0.0);
  double worst = 0.0, released = 0.0;
  int collisions = 0;
  std::size_t contacts_before = 0, most_contacts = 0;
  const std::int64_t steps = std::llround(0.03 / sim.time_step());
  for (std::int64_t k = 0; k < steps; ++k) {
    sim.step();
    const std::size_t c = sim.contact_count();
    if (c > contacts_before) collisions += int(c - contacts_before);
    contacts_before = c;
    most_contacts = std::max(most_contacts, c);
    if (k % 50 == 0) {
      worst = std::max(worst, std::fabs(energy() - e0));
      released = std::max(released, u0 - sim.potential_energy(0.0));
    }
  }
  report("bed in the frame: potential released {:.3e} J, max |E - E0| = {:.2e} J = {:.1e} of it (tol 1e-3), "
         "{} particle collisions, at most {} contacts at once",
         released, worst, worst / released, collisions, most_contacts);
  EXPECT_GT(collisions, 100);  // the particles pile up and collide: the springs take part in the balance
  EXPECT_GT(most_contacts, 10u);
  EXPECT_GT(released, 0.0);
  EXPECT_LT(worst / released, 1e-3);
}

// No frame, or a frame cleared before the first step: the uniform-gravity step, bit for bit.
TEST(RotatingFrame, ClearedFrameLeavesTheUniformGravityStep) {
  const std::vector<Vec3> at = {{0.0, 0.0, 0.0}, {0.0019, 0.0, 0.0005}, {0.05, 0.0, 0.1}};
  auto run = [&](bool set_then_clear) {
    Simulation sim(scattered_particles(at), frictionless_law(1e4, 0.5), far_apart_settings(0.5, 1e-5));
    if (set_then_clear) {
      sim.set_rotating_frame(centrifuge_frame(kOmega));
      sim.clear_rotating_frame();
    }
    sim.run(200);
    return sim.particles().position;
  };
  const auto plain = run(false), cleared = run(true);
  for (std::size_t i = 0; i < plain.size(); ++i) EXPECT_TRUE(plain[i] == cleared[i]);
}

TEST(RotatingFrame, RefusesAZeroAxisAndAMissingSpin) {
  Simulation sim(scattered_particles({{0, 0, 0}}), frictionless_law(1e4, 0.5), far_apart_settings(0.5, 1e-5));
  RotatingFrame f = centrifuge_frame(kOmega);
  f.axis = {};
  EXPECT_THROW(sim.set_rotating_frame(f), InputError);
  f = centrifuge_frame(kOmega);
  f.spin = nullptr;
  EXPECT_THROW(sim.set_rotating_frame(f), InputError);
}

}  // namespace
}  // namespace trapdem
