// Coulomb friction with static and kinetic coefficients: a non-rotating sphere on an inclined
// plane (gravity tilted, the floor wall horizontal), and the kernel's stick/slip rule called
// directly with hand-built contact histories.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/contact/law.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.001;
constexpr double kDensity = 2500.0;
constexpr double kStiffness = 1.0e4;  // N/m: static overlap m g / k_n ~ 1e-8 m
constexpr double kRamp = 0.01;        // s: gravity grows from 0 over this time

struct Incline {
  double start_x, end_x;    // m, position along the slope (x) at the start and end of the run
  double speed;             // m/s, |v| at the end
  double acceleration;      // m/s^2 along +x (down the slope), measured over the last 20 ms
  double elastic_shift;     // m, m g sin / k_t: how far a stuck sphere moves on its tangential spring
};

// A sphere on a horizontal floor; gravity (full magnitude from the start, the sphere resting at its
// equilibrium overlap) tilts towards +x from 0 to atan(slope) over kRamp, so that the tangential
// spring is loaded quasi-statically: a sudden tilt would overshoot the static force by up to
// (1 + e), and a sudden load on an unloaded contact would make F_n oscillate about zero (ramping
// |g| from zero made a sphere at tan = 0.95 mu_s slip in its first steps). Rotation frozen: the
// sphere is a sliding block.
Incline run_incline(double slope, double mu_s, double mu_k, double initial_speed = 0.0) {
  const double m0 = sphere_mass(kRadius, kDensity);
  Particles p;
  p.add(1, {0, 0, kRadius - m0 * kG / kStiffness}, kRadius, kDensity, {initial_speed, 0, 0});
  const double m = p.mass[0];
  SimulationSettings s;
  s.domain = box(0.2);
  s.time_step_fraction = 0.1;
  s.freeze_rotation = true;
  ContactLaw law = frictionless_law(kStiffness, 0.5);
  law.static_friction = mu_s;
  law.kinetic_friction = mu_k;
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  const double angle = std::atan(slope);
  sim.set_gravity([angle](double t) {
    const double a = angle * std::min(1.0, t / kRamp);
    return Vec3{kG * std::sin(a), 0.0, -kG * std::cos(a)};
  });
  const double dt = sim.time_step();
  const auto steps_to = [&](double t) { return std::int64_t(std::llround(t / dt)); };
  sim.run(steps_to(kRamp + 0.01));
  const double t1 = sim.time(), v1 = sim.particles().velocity[0].x;
  sim.run(steps_to(0.02));
  const double t2 = sim.time(), v2 = sim.particles().velocity[0].x;
  return {0.0, sim.particles().position[0].x, norm(sim.particles().velocity[0]), (v2 - v1) / (t2 - t1),
          m * kG * std::sin(angle) / law.tangential_stiffness};
}

double sliding_acceleration(double slope, double mu_k) {
  const double angle = std::atan(slope);
  return kG * (std::sin(angle) - mu_k * std::cos(angle));
}

// A stuck sphere moves only on its tangential spring, m g sin / k_t (~1e-8 m here); allow twice
// that for the dashpot's lag during the ramp. A sliding one travels millimetres.
void expect_stuck(const Incline& r, const char* what) {
  EXPECT_LT(std::fabs(r.end_x - r.start_x), 2.0 * r.elastic_shift) << what;
  // At rest up to the decay of the (damped) tangential oscillation: 1e-6 m/s is ~1e-4 of the
  // speed a 30 ms slide would reach.
  EXPECT_LT(r.speed, 1e-6) << what;
  report("{}: shift {:.2e} m (tol {:.2e}), speed {:.1e} m/s (tol 1e-6)", what, std::fabs(r.end_x - r.start_x),
         2.0 * r.elastic_shift, r.speed);
}

// While sliding, |F_t| = mu_k |F_n| exactly and F_n = m g cos up to the decayed normal
// oscillation (the slow tilt excites it very little, and it has decayed over ~100 periods), so
// the measured acceleration matches g (sin - mu_k cos) to round-off (measured ~1e-12); 1e-8
// relative leaves room for that residue. A wrong coefficient (mu_s instead of mu_k) changes it by
// 10-100 %.
void expect_sliding(const Incline& r, double slope, double mu_k, const char* what) {
  const double a = sliding_acceleration(slope, mu_k);
  EXPECT_GT(r.end_x - r.start_x, 1e-4) << what;
  EXPECT_NEAR(r.acceleration, a, 1e-8 * a) << what;
  report("{}: acceleration {:.6f} vs g(sin - mu_k cos) = {:.6f}, rel. error {:.1e} (tol 1e-8)", what, r.acceleration,
         a, std::fabs(r.acceleration / a - 1.0));
}

}  // namespace

// mu_k < mu_s: the usual case.
TEST(Friction, SticksBelowStaticLimit) {
  expect_stuck(run_incline(0.95 * 0.5, 0.5, 0.3), "tan = 0.95 mu_s");
  // Above mu_k but below mu_s: a sphere at rest stays at rest (static friction holds).
  expect_stuck(run_incline(0.4, 0.5, 0.3), "mu_k < tan < mu_s, from rest");
}

TEST(Friction, SlidesAboveStaticLimitWithKineticAcceleration) {
  expect_sliding(run_incline(1.05 * 0.5, 0.5, 0.3), 1.05 * 0.5, 0.3, "tan = 1.05 mu_s");
  expect_sliding(run_incline(1.0, 0.5, 0.3), 1.0, 0.3, "tan = 1");
}

// Between the coefficients, a sphere already sliding keeps sliding (kinetic friction cannot hold
// it): the hysteresis that distinguishes mu_s from mu_k.
TEST(Friction, SlidingSphereBetweenKineticAndStaticLimitKeepsSliding) {
  expect_sliding(run_incline(0.4, 0.5, 0.3, 0.05), 0.4, 0.3, "mu_k < tan < mu_s, launched");
}

// The paper's Table 2 case mu_s = 0.18 < mu_k = 0.5, outside the ambiguous band between them.
TEST(Friction, KineticAboveStaticOnIncline) {
  expect_stuck(run_incline(0.1, 0.18, 0.5), "mu_s=0.18 mu_k=0.5, tan = 0.1");
  expect_sliding(run_incline(0.6, 0.18, 0.5), 0.6, 0.5, "mu_s=0.18 mu_k=0.5, tan = 0.6");
}

// ---------------------------------------------------------------------------------------------
// The kernel's rule (contact/tangential_coulomb.hpp): stick while |F_t trial| <= mu_s |F_n|; beyond it slide,
// with the force cut back to mu_k |F_n| if it exceeds that (never raised to it); stick again once
// the trial force is inside the kinetic cone. Checked with mu_s = 0.18, mu_k = 0.5 on one call at
// a time. No damping (e = 1), so every expected force
// is a closed-form product and the tolerances are round-off (1e-12 relative).
namespace {

struct KernelSetup {
  LawParams c;
  ContactBodies b;
  Vec3 n{0, 0, 1};
  double overlap = 1e-6;  // m -> F_n = k_n overlap = 0.01 N
  double dt = 1e-6;       // s
  const NormalLinear::Params& spring() const { return c.normal; }
  double fn() const { return spring().kn * overlap; }

  KernelSetup(double restitution = 1.0) {
    ContactLaw law = frictionless_law(1.0e4, restitution);
    law.static_friction = 0.18;
    law.kinetic_friction = 0.5;
    set(law);
    const double m = sphere_mass(kRadius, kDensity);
    b = {.effective_mass = m, .effective_radius = kRadius, .arm_i = kRadius, .arm_j = 0.0, .lever = kRadius,
         .rolling_inertia = 1.4 * m * kRadius * kRadius, .spin_inertia = 0.4 * m * kRadius * kRadius,
         .mean_mass = m, .tangential_mass = m / 3.5};
  }
  void set(const ContactLaw& law) {
    ASSERT_TRUE(law_choices(law) == LawChoices{});  // the law evaluated below: linear, no rolling resistance
    c = law_params(law, law);
  }
  // History whose spring alone gives a tangential force of `ratio` |F_n| along -x.
  ContactHistory history(double ratio, bool sliding) const {
    ContactHistory h;
    h.tangential_spring = {ratio * fn() / spring().kt, 0, 0};
    h.flags = ContactHistory::kTouching | (sliding ? ContactHistory::kSliding : 0u);
    return h;
  }
  ContactForce call(ContactHistory& h, const Vec3& v_rel) const {
    return ContactEvaluator<LawChoices{}>::evaluate(c, b, n, overlap, v_rel, {}, {}, h, dt);
  }
};

constexpr double kRel = 1e-12;

}  // namespace

TEST(FrictionKernel, SticksBelowStaticLimit) {
  KernelSetup k;
  ContactHistory h = k.history(0.17, false);
  const ContactForce f = k.call(h, {});
  EXPECT_NEAR(f.normal_force, k.fn(), kRel * k.fn());
  EXPECT_NEAR(f.tangential.x, -0.17 * k.fn(), kRel * k.fn());
  EXPECT_FALSE(h.sliding());
  EXPECT_TRUE(h.touching());
  // Sticking with the contact moving: the spring grows by v_t dt.
  ContactHistory h2 = k.history(0.10, false);
  const double vt = 0.05 * k.fn() / (k.spring().kt * k.dt);  // adds 0.05 |F_n| to the trial force
  const ContactForce f2 = k.call(h2, {vt, 0, 0});
  EXPECT_NEAR(f2.tangential.x, -0.15 * k.fn(), kRel * k.fn());
  EXPECT_FALSE(h2.sliding());
  EXPECT_NEAR(h2.tangential_spring.x, 0.15 * k.fn() / k.spring().kt, kRel * k.fn() / k.spring().kt);
}

TEST(FrictionKernel, YieldsAboveStaticLimitWithoutRaisingTheForce) {
  KernelSetup k;
  // Trial 0.19 |F_n|: just above mu_s, far below mu_k. The contact is marked sliding, and its
  // force stays the elastic trial force: a yielding contact never pushes harder than its spring.
  ContactHistory h = k.history(0.19, false);
  const ContactForce f = k.call(h, {});
  EXPECT_TRUE(h.sliding());
  EXPECT_NEAR(f.tangential.x, -0.19 * k.fn(), kRel * k.fn());
  EXPECT_NEAR(std::fabs(f.tangential.y) + std::fabs(f.tangential.z), 0.0, kRel * k.fn());
  EXPECT_NEAR(h.tangential_spring.x, 0.19 * k.fn() / k.spring().kt, kRel * k.fn() / k.spring().kt);

  // Driven on past the kinetic cone: the force is cut back to mu_k |F_n| and the spring set to
  // carry exactly that, so F_t is continuous if it sticks next.
  const double vt = 0.4 * k.fn() / (k.spring().kt * k.dt);  // trial 0.59 |F_n|
  const ContactForce f2 = k.call(h, {vt, 0, 0});
  EXPECT_TRUE(h.sliding());
  EXPECT_NEAR(f2.tangential.x, -0.5 * k.fn(), kRel * k.fn());
  EXPECT_NEAR(h.tangential_spring.x, 0.5 * k.fn() / k.spring().kt, kRel * k.fn() / k.spring().kt);
}

// mu_k < mu_s, the usual case: a yielding contact drops from the static to the kinetic force.
TEST(FrictionKernel, YieldingDropsToKineticForceWhenKineticIsLower) {
  KernelSetup k;
  ContactLaw law = frictionless_law(1.0e4, 1.0);
  law.static_friction = 0.5;
  law.kinetic_friction = 0.3;
  k.set(law);
  ContactHistory h = k.history(0.52, false);
  const ContactForce f = k.call(h, {});
  EXPECT_TRUE(h.sliding());
  EXPECT_NEAR(f.tangential.x, -0.3 * k.fn(), kRel * k.fn());
}

TEST(FrictionKernel, SticksAgainWhenTrialFallsInsideKineticCone) {
  KernelSetup k;
  ContactHistory h = k.history(0.5, true);  // sliding, spring at the kinetic limit
  // The contact reverses: the trial force drops to 0.4 |F_n|, inside the kinetic cone: it sticks
  // with the trial force.
  const double vt = -0.1 * k.fn() / (k.spring().kt * k.dt);
  const ContactForce f = k.call(h, {vt, 0, 0});
  EXPECT_FALSE(h.sliding());
  EXPECT_NEAR(f.tangential.x, -0.4 * k.fn(), kRel * k.fn());
  // From sticking, 0.4 |F_n| > mu_s |F_n| marks it sliding again, with the same force.
  const ContactForce f2 = k.call(h, {});
  EXPECT_TRUE(h.sliding());
  EXPECT_NEAR(f2.tangential.x, -0.4 * k.fn(), kRel * k.fn());
}

TEST(FrictionKernel, KineticForceScalesWithDampedNormalForce) {
  // With damping the normal force includes the dashpot; sliding friction is mu_k times it, in
  // the direction of the trial force.
  KernelSetup k(0.5);
  ContactHistory h = k.history(0.6, true);
  const Vec3 v{0.02, 0.01, -0.03};  // approaching (v_n < 0) and slipping along +x, +y
  const ContactForce f = k.call(h, v);
  EXPECT_TRUE(h.sliding());
  EXPECT_GT(f.normal_force, k.fn());  // the dashpot resists the approach
  EXPECT_NEAR(norm(f.tangential), 0.5 * f.normal_force, kRel * k.fn());
  EXPECT_LT(f.tangential.x, 0.0);
  EXPECT_LT(f.tangential.y, 0.0);
  EXPECT_NEAR(dot(f.tangential, k.n), 0.0, kRel * k.fn());
}
