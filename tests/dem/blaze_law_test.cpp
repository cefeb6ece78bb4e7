// Blaze-DEM's contact law as its public code has it (issue 36): the viscous tangential force
// without spring or Coulomb cap (contact/tangential_blaze_viscous.hpp), the per-step angular
// damping (contact/rolling_angular_damping.hpp) and the lowered restitution of its damping
// (ContactLaw::damping_restitution). Each against its hand formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <utility>

#include "dem/contact/law.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kRadius = 0.001;    // m
constexpr double kDensity = 2500.0;  // kg/m^3
constexpr double kStiffness = 1.0e4; // N/m
constexpr double kReferenceStep = 1.0e-7;  // s, Blaze's dt (a few times 1e-8 s: see docs/config.md)

constexpr LawChoices kBlaze{.tangential = TangentialModel::blaze_viscous};

ContactLaw blaze_law(double mu_k) {
  ContactLaw law = frictionless_law(kStiffness, 0.9);
  law.tangential_model = TangentialModel::blaze_viscous;
  law.static_friction = 0.18;
  law.kinetic_friction = mu_k;
  law.reference_time_step = kReferenceStep;
  return law;
}

// One sphere-sphere contact of equal spheres through the evaluator, as the batch loops run it.
ContactForce pair_contact(const ContactLaw& law, double overlap, const Vec3& v_rel, const Vec3& w_i, const Vec3& w_j,
                          double dt) {
  const double m = sphere_mass(kRadius, kDensity);
  const Body body{m, kRadius, 1.0 / (0.4 * m * kRadius * kRadius)};
  const ContactBodies b = reduce_bodies<kBlaze, SecondBody::sphere>(body, body, overlap, 2.0 * kRadius - overlap);
  ContactHistory h;
  return ContactEvaluator<kBlaze>::evaluate(law_params(law, law), b, {0, 0, 1}, overlap, v_rel, w_i, w_j, h, dt);
}

}  // namespace

// F_t = -mu_k (m_i + m_j)/2 (u0 / dt_ref) v_t / V (Collision_Response_Particle_Particle), with
// v_t the contact points' tangential relative velocity and V = |v_i - v_j|. Checked for two normal
// forces a decade apart (the force must not change: Blaze's strength does not depend on F_n), with
// and without spin (spin changes v_t, not V), to 1e-12 relative (round-off of a few operations).
TEST(BlazeViscous, ForceIsTheHandFormulaAndIndependentOfTheNormalForce) {
  const double mu_k = 0.5, u0 = 5.0e-4, dt = 1.0e-8;  // dt small: the one-step bound does not bind
  const ContactLaw law = blaze_law(mu_k);
  const double m = sphere_mass(kRadius, kDensity);
  const Vec3 v_rel{0.02, -0.01, -0.005};  // m/s: sliding in x, y; approaching in z
  const Vec3 w_i{0.0, 3.0, 0.0}, w_j{-1.0, 0.0, 2.0};  // rad/s
  for (const double overlap : {1e-7, 1e-6}) {
    const ContactForce f = pair_contact(law, overlap, v_rel, w_i, w_j, dt);
    // Contact point at the middle of the overlap: arms r - overlap/2 along -n for i, +n for j.
    const double arm = kRadius - 0.5 * overlap;
    const Vec3 n{0, 0, 1};
    const Vec3 v = v_rel - cross(arm * w_i + arm * w_j, n);
    const Vec3 vt = v - dot(v, n) * n;
    const Vec3 expected = -(mu_k * m * u0 / kReferenceStep / norm(v_rel)) * vt;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(f.tangential[a], expected[a], 1e-12 * norm(expected)) << overlap;
    EXPECT_GT(f.normal_force, 0.0);
  }
  // Without spin the slip is the same at both overlaps (with spin the contact point's arm r - delta/2 differs).
  const Vec3 low = pair_contact(law, 1e-7, v_rel, Vec3{}, Vec3{}, dt).tangential;
  const Vec3 high = pair_contact(law, 1e-6, v_rel, Vec3{}, Vec3{}, dt).tangential;
  EXPECT_NEAR(norm(low - high), 0.0, 1e-12 * norm(low));
}

// V = 0 exactly (only spin slips the contact): Blaze takes V = 1 cm/s.
TEST(BlazeViscous, AtZeroCentreSpeedUsesTheRestSpeed) {
  const double mu_k = 0.2, dt = 1.0e-9;
  const ContactLaw law = blaze_law(mu_k);
  const double m = sphere_mass(kRadius, kDensity);
  const ContactForce f = pair_contact(law, 1e-6, Vec3{}, {0.0, 2.0, 0.0}, Vec3{}, dt);
  const double arm = kRadius - 0.5e-6;
  const double slip = -2.0 * arm;  // m/s along x: v = -(w_i x n) a = -(2 e_y x e_z) a
  EXPECT_NEAR(f.tangential.x, -mu_k * m * 5.0e-4 / kReferenceStep / 0.01 * slip, 1e-12 * std::fabs(f.tangential.x));
  EXPECT_EQ(f.tangential.y, 0.0);
}

// A slow contact at a long step: Blaze's coefficient would reverse the slip within the step; the
// force is bounded by what stops it, m_t |v_t| / dt, m_t = [2/m + 2 a^2 / I]^-1 for equal spheres.
TEST(BlazeViscous, ForceIsBoundedByWhatStopsTheSlipWithinTheStep) {
  const ContactLaw law = blaze_law(0.5);
  const double m = sphere_mass(kRadius, kDensity), inertia = 0.4 * m * kRadius * kRadius;
  const double dt = 1.0e-5, overlap = 1e-7, arm = kRadius - 0.5 * overlap;
  const Vec3 v_rel{1.0e-4, 0.0, 0.0};
  const ContactForce f = pair_contact(law, overlap, v_rel, Vec3{}, Vec3{}, dt);
  const double tangential_mass = 1.0 / (2.0 / m + 2.0 * arm * arm / inertia);
  EXPECT_NEAR(f.tangential.x, -tangential_mass * 1.0e-4 / dt, 1e-12 * tangential_mass);
  EXPECT_LT(tangential_mass * 1.0e-4 / dt, 0.5 * m * 5.0e-4 / kReferenceStep);  // the bound binds here
}

// A sphere on a floor at a step 32x Blaze's, started sliding without spin (v0) or spinning in
// place (w0; V = 0 then, and Blaze's coefficient, at its rest speed, would reverse the slip
// within one step): the viscous force brakes the slip until the sphere rolls. The kinetic energy
// never grows (1e-12 of its start: round-off) and the slip never reverses. Without the one-step
// bound the spinning start reverses its slip at the first steps. At the end the sphere rolls with
// the angular momentum about the contact point kept: v = 5/7 v0, or v = 2/7 r w0.
TEST(BlazeViscous, SphereOnAFloorNeverGainsEnergyAndEndsRolling) {
  const ContactLaw law = blaze_law(0.5);
  const double m = sphere_mass(kRadius, kDensity), inertia = 0.4 * m * kRadius * kRadius;
  struct Start {
    Vec3 velocity, spin;
    double rolling_speed;  // m/s
  };
  const double v0 = 0.05, w0 = 50.0;
  for (const Start& start : {Start{{v0, 0, 0}, Vec3{}, 5.0 / 7.0 * v0}, Start{Vec3{}, {0, w0, 0}, 2.0 / 7.0 * kRadius * w0}}) {
    Particles p;
    p.add(1, {0, 0, kRadius - m * 9.81 / kStiffness}, kRadius, kDensity, start.velocity, start.spin);
    SimulationSettings s;
    s.domain = box(0.5);
    s.time_step_fraction = 0.1;
    Simulation sim(std::move(p), law, s);
    sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
    sim.set_gravity(Vec3{0, 0, -9.81});
    ASSERT_GT(sim.time_step(), 10.0 * kReferenceStep);
    const Particles& q = sim.particles();
    auto kinetic = [&] { return 0.5 * m * norm2(q.velocity[0]) + 0.5 * inertia * norm2(q.angular_velocity[0]); };
    // The contact point's slip: v - w x (arm n), the arm the centre's height above the floor.
    auto slip = [&] { return q.velocity[0].x - q.angular_velocity[0].y * q.position[0].z; };
    const double e0 = kinetic(), slip0 = slip();
    double previous = e0;
    for (int step = 0; step < 2000; ++step) {
      sim.step();
      const double e = kinetic();
      ASSERT_LE(e, previous + 1e-12 * e0) << "step " << step;
      ASSERT_GE(slip() * slip0, -1e-12 * slip0 * slip0) << "slip reversed at step " << step;
      previous = e;
    }
    EXPECT_NEAR(slip(), 0.0, 1e-9 * std::fabs(slip0));
    EXPECT_NEAR(q.velocity[0].x, start.rolling_speed, 2e-3 * start.rolling_speed);
  }
}

// The Tresca reading: a contact sheared at a constant slip rate loads its spring elastically
// (F_t = -k_t s, s = v_t t) until |F_t| reaches S = mu_k (m_i + m_j)/2 u0 / dt_ref, and then carries
// S whatever F_n: the same S at two normal forces a decade apart (to 1e-12 relative: round-off).
TEST(BlazeTresca, SpringCappedAtAStrengthIndependentOfTheNormalForce) {
  constexpr LawChoices kTresca{.tangential = TangentialModel::blaze_tresca};
  ContactLaw law = blaze_law(0.5);
  law.tangential_model = TangentialModel::blaze_tresca;
  law.restitution = 1.0;  // no dashpot: the spring's force alone
  const double m = sphere_mass(kRadius, kDensity);
  const double strength = 0.5 * m * 5.0e-4 / kReferenceStep;  // N
  const Body body{m, kRadius, 1.0 / (0.4 * m * kRadius * kRadius)};
  const LawParams params = law_params(law, law);
  const double dt = 1e-6, slip = 1e-3;  // s, m/s
  for (const double overlap : {1e-7, 1e-6}) {
    const ContactBodies b = reduce_bodies<kTresca, SecondBody::sphere>(body, body, overlap, 2 * kRadius - overlap);
    ContactHistory h;
    bool capped = false;
    for (int step = 1; step <= 200000 && !capped; ++step) {
      const ContactForce f = ContactEvaluator<kTresca>::evaluate(params, b, {0, 0, 1}, overlap, {slip, 0, 0}, Vec3{},
                                                                 Vec3{}, h, dt);
      const double elastic = law.tangential_stiffness * slip * dt * step;
      if (elastic < strength) {
        ASSERT_NEAR(f.tangential.x, -elastic, 1e-9 * strength) << step;
        ASSERT_FALSE(h.sliding());
      } else {
        EXPECT_NEAR(f.tangential.x, -strength, 1e-12 * strength);
        EXPECT_TRUE(h.sliding());
        capped = true;
      }
    }
    EXPECT_TRUE(capped) << overlap;
  }
}

// omega <- omega (1 - mu_r) per reference step, applied at that rate in time: a free spinning
// sphere at two engine steps has omega(t) = omega0 (1 - mu_r)^(t / dt_ref) at each, to 1e-12
// relative (the per-step factor's round-off over a few hundred steps).
TEST(AngularDamping, SpinDecaysAtTheReferenceRateWhateverTheStep) {
  const double mu_r = 0.001;
  for (const double fraction : {0.05, 0.2}) {
    ContactLaw law = frictionless_law(kStiffness, 0.9);
    law.rolling_model = RollingModel::angular_damping;
    law.rolling_friction = mu_r;
    law.reference_time_step = kReferenceStep;
    Particles p;
    const Vec3 w0{0.0, 0.0, 100.0};
    p.add(1, Vec3{}, kRadius, kDensity, Vec3{}, w0);
    SimulationSettings s;
    s.domain = box(0.5);
    s.time_step_fraction = fraction;
    Simulation sim(std::move(p), law, s);
    sim.set_gravity(Vec3{});
    const int steps = 200;
    for (int k = 0; k < steps; ++k) sim.step();
    const double t = steps * sim.time_step();
    const double expected = w0.z * std::pow(1.0 - mu_r, t / kReferenceStep);
    EXPECT_NEAR(sim.particles().angular_velocity[0].z, expected, 1e-12 * w0.z) << "fraction " << fraction;
    EXPECT_LT(expected, 0.9 * w0.z);  // the decay is visible over the run
  }
}

// mu_r = 0 is no damping; a contact carries no rolling torque (only r x F_t).
TEST(AngularDamping, NoContactTorqueAndNoDampingWithoutRollingFriction) {
  ContactLaw law = frictionless_law(kStiffness, 0.9);
  law.rolling_model = RollingModel::angular_damping;
  law.reference_time_step = kReferenceStep;
  law.rolling_friction = 0.0;
  EXPECT_EQ(spin_retention(law, 1e-5), 1.0);
  law.rolling_friction = 0.3;
  EXPECT_DOUBLE_EQ(spin_retention(law, 2.0 * kReferenceStep), 0.49);
  constexpr LawChoices choices{.rolling = RollingModel::angular_damping};
  const double m = sphere_mass(kRadius, kDensity);
  const Body body{m, kRadius, 1.0 / (0.4 * m * kRadius * kRadius)};
  const ContactBodies b = reduce_bodies<choices, SecondBody::sphere>(body, body, 1e-7, 2 * kRadius - 1e-7);
  ContactHistory h;
  const ContactForce f = ContactEvaluator<choices>::evaluate(law_params(law, law), b, {0, 0, 1}, 1e-7, Vec3{},
                                                             {5.0, 0.0, 0.0}, Vec3{}, h, 1e-6);
  EXPECT_EQ(norm(f.rolling_torque), 0.0);
}

// Blaze-DEM lowers e by 0.03808 for 0.3 <= e <= 0.9 before it sets c_n (KSimulationData.cpp).
TEST(BlazeRestitution, LowersTheRestitutionInItsRangeOnly) {
  ContactLaw law;
  law.damping_model = DampingModel::restitution_blaze;
  for (const auto& [e, expected] : {std::pair{0.9, 0.86192}, std::pair{0.3, 0.26192}, std::pair{0.95, 0.95},
                                    std::pair{0.2, 0.2}, std::pair{1.0, 1.0}}) {
    law.restitution = e;
    EXPECT_DOUBLE_EQ(law.damping_restitution(), expected) << e;
  }
  ContactLaw plain = law;
  plain.damping_model = DampingModel::restitution;
  plain.restitution = 0.86192;
  law.restitution = 0.9;
  EXPECT_DOUBLE_EQ(law.damping_ratio(), plain.damping_ratio());
}

// Every law the dispatch table compiles marks its contacts touching (the evaluator does it, not
// the tangential model), so that no law's contacts are dropped at a list rebuild
// (history_archive.cpp keeps touching contacts only).
namespace {
template <std::size_t... K>
void expect_every_law_marks_touching(std::index_sequence<K...>) {
  const ContactLaw law = blaze_law(0.3);
  const double m = sphere_mass(kRadius, kDensity);
  const Body body{m, kRadius, 1.0 / (0.4 * m * kRadius * kRadius)};
  auto one = [&]<LawChoices kLaw>() {
    const ContactBodies b = reduce_bodies<kLaw, SecondBody::sphere>(body, body, 1e-7, 2 * kRadius - 1e-7);
    ContactHistory h;
    ContactEvaluator<kLaw>::evaluate(law_params(law, law), b, {0, 0, 1}, 1e-7, {0.01, 0, 0}, Vec3{}, Vec3{}, h, 1e-6);
    EXPECT_TRUE(h.touching()) << "law number " << LawAxes::number_of(kLaw);
  };
  (one.template operator()<LawAxes::numbered(K).canonical()>(), ...);
}
}  // namespace

TEST(ContactLawDispatch, EveryLawMarksItsContactsTouching) {
  expect_every_law_marks_touching(std::make_index_sequence<LawAxes::kCount>{});
}
