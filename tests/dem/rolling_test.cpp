// Rolling resistance: a sphere rolling on a floor wall under the constant torque model (type A),
// and a sphere on a slope under the elastic-plastic spring-dashpot model (type C, EPSD).
// At a wall the lever arm is the particle radius r, so the limiting torque is M = mu_r r |F_n|.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.001;
constexpr double kDensity = 2500.0;
constexpr double kStiffness = 1.0e4;  // N/m: static overlap m g / k_n ~ 1e-8 m = 1e-5 r

ContactLaw rolling_law(RollingModel model, double mu_r) {
  ContactLaw law = frictionless_law(kStiffness, 0.5);
  law.static_friction = 1.0;  // high: the sphere rolls, it never slides
  law.kinetic_friction = 1.0;
  law.rolling_friction = mu_r;
  law.rolling_model = model;
  return law;
}

Simulation sphere_on_floor(const ContactLaw& law, const Vec3& velocity, const Vec3& spin,
                           double time_step_fraction = 0.1) {
  const double m = sphere_mass(kRadius, kDensity);
  Particles p;
  p.add(1, {0, 0, kRadius - m * kG / kStiffness}, kRadius, kDensity, velocity, spin);
  SimulationSettings s;
  s.domain = box(0.2);
  s.time_step_fraction = time_step_fraction;
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  return sim;
}

}  // namespace

// Energy balance: the kinetic energy of pure rolling, (1/2) m v0^2 (1 + 2/5) = 0.7 m v0^2, is
// spent by the torque mu_r r m g over the angle s / r: s = 0.7 v0^2 / (mu_r g). (Equivalently
// the deceleration is mu_r g / 1.4.)
//
// Tolerance 1e-3 relative: the lever arm the kernel uses for the friction torque is the centre-
// to-contact distance r - delta (delta / r ~ 1e-5), the tangential spring stores a shift of
// F_t / k_t ~ 1e-9 m, and the last step before rest is cut short by the torque bound
// I w / dt (at most v0 dt ~ 1e-7 m, 1e-4 of s). A lever arm of r/2 or the effective radius
// would double s; a missing rotational term would change 0.7 to 0.5.
TEST(Rolling, ConstantTorqueStopsAtEnergyBalanceDistanceAndStaysAtRest) {
  for (const double mu_r : {0.1, 0.3}) {
    const double v0 = 0.05;
    Simulation sim = sphere_on_floor(rolling_law(RollingModel::constant_torque, mu_r), {v0, 0, 0},
                                     {0, v0 / kRadius, 0});
    const double expected = 0.7 * v0 * v0 / (mu_r * kG);
    const double t_stop = v0 / (mu_r * kG / 1.4);
    const std::int64_t steps = std::llround(1.1 * t_stop / sim.time_step());
    sim.run(steps);
    const double s = sim.particles().position[0].x;
    report("constant torque mu_r={}: s = {:.6e} m vs 0.7 v0^2/(mu_r g) = {:.6e} m, rel. error {:.1e} (tol 1e-3)", mu_r,
           s, expected, std::fabs(s / expected - 1.0));
    EXPECT_NEAR(s, expected, 1e-3 * expected) << "mu_r = " << mu_r;

    // At rest it stays at rest: the torque is bounded by what stops the rolling in one step, so it
    // does not flip sign every step (chatter). Over another 20 ms (~6000 steps) the sphere must
    // not drift and its spin must stay at round-off level. A chattering torque mu_r r m g would
    // give |w| ~ mu_r r m g dt / I ~ 0.2 rad/s and drift of v dt per step.
    const double x_rest = sim.particles().position[0].x;
    double max_spin = 0.0, max_speed = 0.0;
    for (int k = 0; k < 6000; ++k) {
      sim.step();
      max_spin = std::max(max_spin, norm(sim.particles().angular_velocity[0]));
      max_speed = std::max(max_speed, norm(sim.particles().velocity[0]));
    }
    const double drift = std::fabs(sim.particles().position[0].x - x_rest);
    report("  at rest: max |w| {:.1e} rad/s (tol 1e-6), max |v| {:.1e} m/s (tol 1e-9), drift {:.1e} m (tol 1e-9)",
           max_spin, max_speed, drift);
    EXPECT_LT(max_spin, 1e-6);   // rad/s; r |w| = 1e-9 m/s
    EXPECT_LT(max_speed, 1e-9);  // m/s
    EXPECT_LT(drift, 1e-9);      // m, 1e-6 of r
  }
}

namespace {

struct SlopeRun {
  double shift;         // m, down-slope displacement at the end
  double speed;         // m/s at the end
  double acceleration;  // m/s^2 over the last 20 ms
  double time_step;     // s
};

// Gravity tilts towards +x from 0 to atan(slope) over 10 ms (quasi-static loading of the rolling
// and tangential springs), then holds for 30 ms.
SlopeRun sphere_on_slope(double slope, double mu_r, RollingModel model = RollingModel::elastic_plastic,
                         double time_step_fraction = 0.1) {
  Simulation sim = sphere_on_floor(rolling_law(model, mu_r), {}, {}, time_step_fraction);
  const double angle = std::atan(slope), ramp = 0.01;
  sim.set_gravity([=](double t) {
    const double a = angle * std::min(1.0, t / ramp);
    return Vec3{kG * std::sin(a), 0.0, -kG * std::cos(a)};
  });
  const double dt = sim.time_step();
  sim.run(std::llround(0.02 / dt));
  const double t1 = sim.time(), v1 = sim.particles().velocity[0].x;
  sim.run(std::llround(0.02 / dt));
  const double t2 = sim.time(), v2 = sim.particles().velocity[0].x;
  return {sim.particles().position[0].x, norm(sim.particles().velocity[0]), (v2 - v1) / (t2 - t1), dt};
}

}  // namespace

// Statics of a sphere on a slope: friction F = m g sin holds it, and its moment r F about the
// centre must be balanced by the rolling torque, at most mu_r r m g cos: at rest while
// tan(angle) < mu_r. Beyond, the torque is fully mobilised (no dashpot, Ai et al. eq. 18) and the
// sphere rolls with a = g (sin - mu_r cos) / 1.4.
TEST(Rolling, ElasticPlasticRestsOnSlopeBelowRollingLimit) {
  const double mu_r = 0.2;
  const SlopeRun r = sphere_on_slope(0.5 * mu_r, mu_r);
  // At rest, the sphere has turned on its rolling spring by M / k_r with k_r = 2.25 k_n mu_r^2 r^2,
  // which moves the centre by r M / k_r ~ 1e-8 m; allow 1e-7 m. Rolling for 30 ms would move it
  // ~1 mm.
  report("EPSD tan = mu_r/2: shift {:.2e} m (tol 1e-7), speed {:.1e} m/s (tol 1e-7)", r.shift, r.speed);
  EXPECT_LT(std::fabs(r.shift), 1e-7);
  EXPECT_LT(r.speed, 1e-7);  // m/s: the EPSD dashpot has damped the rolling oscillation
}

TEST(Rolling, ElasticPlasticRollsAwayAboveRollingLimit) {
  const double mu_r = 0.2, slope = 1.5 * mu_r;
  const SlopeRun r = sphere_on_slope(slope, mu_r);
  const double angle = std::atan(slope);
  const double a = kG * (std::sin(angle) - mu_r * std::cos(angle)) / 1.4;
  // Fully mobilised torque mu_r r |F_n| with |F_n| = m g cos up to a decayed oscillation; the
  // friction torque uses the arm r - delta (1e-5 relative): 1e-4 relative tolerance.
  report("EPSD tan = 1.5 mu_r: acceleration {:.6f} vs g(sin - mu_r cos)/1.4 = {:.6f}, rel. error {:.1e} (tol 1e-4)",
         r.acceleration, a, std::fabs(r.acceleration / a - 1.0));
  EXPECT_GT(r.shift, 1e-4);
  EXPECT_NEAR(r.acceleration, a, 1e-4 * a);
}

// The constant torque's bound (what stops the relative rolling within one step, I w / dt) cannot
// hold a steady torque below the limit without motion: a torque T applied every step is balanced
// only once the rolling velocity is T dt / I, so the sphere creeps down a slope it should rest on,
// at w = m g sin(angle) r dt / I (I = 2/5 m r^2 at a wall: r w = 2.5 g sin(angle) dt), at a speed
// proportional to the time step. This is why its strength in quasi-static shear depends on the
// step (docs/element.md, "Rolling resistance and the time step"); EPSD's spring holds the torque
// at rest (above). Tolerance 1e-3 relative: the arm of the friction torque is r - delta (1e-5)
// and the creep is steady to round-off after ~100 steps (the error falls by I / (I + m r^2) a step).
TEST(Rolling, ConstantTorqueCreepsBelowItsLimitAtASpeedProportionalToTheStep) {
  const double mu_r = 0.2, slope = 0.5 * mu_r;
  const double angle = std::atan(slope);
  double creep[2];
  for (int k = 0; k < 2; ++k) {
    const double fraction = k == 0 ? 0.1 : 0.05;
    const SlopeRun r = sphere_on_slope(slope, mu_r, RollingModel::constant_torque, fraction);
    const double dt = r.time_step;
    const double expected = 2.5 * kG * std::sin(angle) * dt;  // m/s, r w
    report("constant torque, tan = mu_r/2, dt {:.3e} s: speed {:.6e} m/s vs 2.5 g sin dt = {:.6e}, rel. error {:.1e} "
           "(tol 1e-3), acceleration {:.1e} m/s^2",
           dt, r.speed, expected, std::fabs(r.speed / expected - 1.0), r.acceleration);
    EXPECT_NEAR(r.speed, expected, 1e-3 * expected) << "time step fraction " << fraction;
    EXPECT_LT(std::fabs(r.acceleration), 1e-3 * expected / 0.02);  // steady: no acceleration
    creep[k] = r.speed;
  }
  EXPECT_NEAR(creep[1] / creep[0], 0.5, 1e-3);  // half the step, half the creep
}

// Walls whose laws make different choices (here a ceiling without rolling resistance beside an
// EPSD or constant-torque floor) run the wall batch in stretches of equal choices, each through
// the loop compiled for its choices (src/dem/wall_sweep.cpp), instead of the whole batch through
// one. The sphere on the floor must end where it ends without the ceiling. Tolerance 1e-9
// relative: the vectorised loop and its scalar remainder may contract multiply-adds differently
// (round-off, ~1e-16 per step), amplified over the run; a law that read another wall's parameters
// or choices would differ at the first per cent.
TEST(Rolling, WallsOfOtherRollingModelsLeaveTheFloorContactUnchanged) {
  for (const RollingModel model : {RollingModel::constant_torque, RollingModel::elastic_plastic}) {
    const ContactLaw law = rolling_law(model, 0.2);
    ContactLaw ceiling_law = law;
    ceiling_law.rolling_model = RollingModel::none;
    ceiling_law.static_friction = ceiling_law.kinetic_friction = 0.1;
    const double v0 = 0.05;
    Simulation alone = sphere_on_floor(law, {v0, 0, 0}, {0, 0.5 * v0 / kRadius, 0});  // slips, then rolls
    Simulation mixed = sphere_on_floor(law, {v0, 0, 0}, {0, 0.5 * v0 / kRadius, 0});
    mixed.add_wall(Wall::plane("ceiling", {0, 0, 0.1}, {0, 0, -1}, ceiling_law));
    const std::int64_t steps = std::llround(0.03 / alone.time_step());
    alone.run(steps);
    mixed.run(steps);
    const Vec3 xa = alone.particles().position[0], xm = mixed.particles().position[0];
    const Vec3 wa = alone.particles().angular_velocity[0], wm = mixed.particles().angular_velocity[0];
    report("{}: x {:.9e} vs {:.9e} m, w_y {:.9e} vs {:.9e} rad/s", to_string(model), xa.x, xm.x, wa.y, wm.y);
    EXPECT_GT(xa.x, 1e-4) << "the sphere should have moved";
    EXPECT_NEAR(xm.x, xa.x, 1e-9 * std::fabs(xa.x)) << to_string(model);
    EXPECT_NEAR(wm.y, wa.y, 1e-9 * std::fabs(wa.y) + 1e-12) << to_string(model);
    EXPECT_NEAR(mixed.walls()[0].force.z, alone.walls()[0].force.z, 1e-9 * std::fabs(alone.walls()[0].force.z));
  }
}
