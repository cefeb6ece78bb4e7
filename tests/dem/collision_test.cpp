// Binary collisions against the linear spring-dashpot's analytic coefficient of restitution.
// With c_n = 2 beta sqrt(m* k_n), beta = -ln e / sqrt(ln^2 e + pi^2), a contact that ends when the
// overlap returns to zero releases the bodies with relative normal velocity -e times the incoming
// one, whatever the masses (formulas.md, "Contact").
//
// Tolerance, from the time step: the dashpot force jumps from 0 to c_n v_in when the contact
// starts and from -c_n v_out to 0 when it ends, at instants that fall inside a step. Velocity
// Verlet then misplaces up to about half a step of each jump: |dv| <~ (c_n / 2 m*) dt (v_in + v_out),
// i.e. |e_measured - e| <~ beta w dt (1 + e) with w = sqrt(k_n / m*). The spring itself is
// integrated to second order, which adds (w dt)^2 (the only term left for e = 1). With
// dt = 0.004 sqrt(m_min / k_n) this is 0.05-0.2 % of e; a damping coefficient off by any factor
// that matters (e.g. beta instead of 2 beta) moves e by tens of per cent.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kStiffness = 1.0e4;   // N/m: overlaps stay ~2 % of the radius at 1 m/s
constexpr double kDtFraction = 0.004;  // of sqrt(m_min / k_n): ~600 steps per contact

struct Sphere {
  double radius, density;
};

double damping_ratio(double e) { return e >= 1.0 ? 0.0 : -std::log(e) / std::hypot(std::log(e), std::numbers::pi); }

// The bound explained at the top of the file.
double restitution_tolerance(double e, double omega_dt) {
  return damping_ratio(e) * omega_dt * (1.0 + e) + omega_dt * omega_dt;
}

std::size_t index_of(const Particles& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  ADD_FAILURE() << "no particle with id " << id;
  return 0;
}

struct PairCollision {
  double restitution;     // measured
  double omega_dt;        // sqrt(k_n / m*) dt
  double momentum_error;  // |p_after - p_before| / (m_a |v_a| + m_b |v_b|)
};

// Sphere a moves along +x into sphere b (moving along -x); no gravity, no walls, a large domain.
PairCollision collide(Sphere a, Sphere b, double restitution) {
  const double gap = 0.01 * std::min(a.radius, b.radius);
  const double va = 0.6, vb = -0.4;
  Particles p;
  p.add(1, {-(a.radius + 0.5 * gap), 0.0, 0.0}, a.radius, a.density, {va, 0.0, 0.0});
  p.add(2, {b.radius + 0.5 * gap, 0.0, 0.0}, b.radius, b.density, {vb, 0.0, 0.0});
  const double ma = p.mass[0], mb = p.mass[1];
  SimulationSettings s;
  s.domain = box(0.1);
  s.time_step_fraction = kDtFraction;
  Simulation sim(std::move(p), frictionless_law(kStiffness, restitution), s);
  sim.set_gravity(Vec3{0, 0, 0});
  const double m_eff = ma * mb / (ma + mb);
  const double omega_dt = std::sqrt(kStiffness / m_eff) * sim.time_step();

  struct State {
    double approach;  // relative normal velocity, > 0 when approaching
    double separation;
    Vec3 momentum;
  };
  auto state = [&] {
    const Particles& q = sim.particles();
    const std::size_t i = index_of(q, 1), j = index_of(q, 2);
    const Vec3 d = q.position[j] - q.position[i];
    return State{dot(q.velocity[i] - q.velocity[j], d / norm(d)), norm(d) - q.radius[i] - q.radius[j],
                 q.mass[i] * q.velocity[i] + q.mass[j] * q.velocity[j]};
  };
  const State before = state();
  bool touched = false;
  for (int steps = 0; steps < 100000; ++steps) {
    sim.step();
    const State now = state();
    if (now.separation < 0.0) touched = true;
    if (touched && now.separation > 0.0)
      return {-now.approach / before.approach, omega_dt,
              norm(now.momentum - before.momentum) / (ma * std::fabs(va) + mb * std::fabs(vb))};
  }
  ADD_FAILURE() << "the spheres did not separate";
  return {0.0, omega_dt, 0.0};
}

}  // namespace

class PairRestitution : public ::testing::TestWithParam<double> {};

TEST_P(PairRestitution, HeadOnCollisionLeavesWithSetRestitutionForAnyMassRatio) {
  const double e = GetParam();
  // Mass ratios 1, 2.3 (denser but smaller sphere), 8 and 27 (larger radius).
  const std::pair<Sphere, Sphere> cases[] = {
      {{0.001, 2500.0}, {0.001, 2500.0}},
      {{0.001, 7800.0}, {0.0015, 1000.0}},
      {{0.002, 2500.0}, {0.001, 2500.0}},
      {{0.001, 2500.0}, {0.003, 2500.0}},
  };
  for (const auto& [a, b] : cases) {
    const PairCollision r = collide(a, b, e);
    const double tol = restitution_tolerance(e, r.omega_dt);
    report("pair e={} m_a={:.3g} m_b={:.3g}: |e_meas - e| = {:.2e} (tol {:.2e}), momentum {:.1e}", e,
           sphere_mass(a.radius, a.density), sphere_mass(b.radius, b.density), std::fabs(r.restitution - e), tol,
           r.momentum_error);
    EXPECT_NEAR(r.restitution, e, tol) << "radii " << a.radius << ", " << b.radius << " m, densities " << a.density
                                       << ", " << b.density << " kg/m3";
    // Equal and opposite forces: momentum is conserved to round-off (a few ulps of the momenta).
    EXPECT_LT(r.momentum_error, 1e-13);
  }
}

INSTANTIATE_TEST_SUITE_P(Collision, PairRestitution, ::testing::Values(0.3, 0.6, 0.9, 1.0));

namespace {

// A sphere (r = 1 mm glass) falls on a wall: it starts just above it with the speed of a drop
// from h = v^2 / 2g (5 cm for 1 m/s) so that the free fall needs no steps, under gravity.
// Returns the measured restitution and w dt.
std::pair<double, double> drop_on_wall(const Wall& wall, const Vec3& start, const Vec3& velocity, const Vec3& gravity,
                                       double e) {
  const double r = 0.001;
  Particles p;
  p.add(7, start, r, 2500.0, velocity);
  const double m = p.mass[0];
  SimulationSettings s;
  s.domain = box(0.1);
  s.time_step_fraction = kDtFraction;
  Simulation sim(std::move(p), frictionless_law(wall.law.normal_stiffness, e), s);
  sim.set_gravity(gravity);
  sim.add_wall(wall);
  const double omega_dt = std::sqrt(wall.law.normal_stiffness / m) * sim.time_step();
  auto gap_and_speed = [&](double& gap) {
    const WallProximity near = wall_proximity(sim.walls()[0], sim.particles().position[0]);
    gap = near.distance - r;
    return dot(sim.particles().velocity[0], near.normal);  // > 0: moving away
  };
  double gap;
  double v_in = gap_and_speed(gap);
  bool touched = false;
  for (int steps = 0; steps < 100000; ++steps) {
    sim.step();
    const double v = gap_and_speed(gap);
    if (!touched && gap > 0.0) v_in = v;  // the last free-flight velocity before the contact
    if (gap < 0.0) touched = true;
    if (touched && gap > 0.0) return {-v / v_in, omega_dt};
  }
  ADD_FAILURE() << "the sphere did not rebound";
  return {0.0, omega_dt};
}

}  // namespace

class WallRestitution : public ::testing::TestWithParam<double> {};

// Tolerance: the time-step bound above with m* = m, plus gravity's impulse during the contact
// (g t_c at each end, at most 2 g t_c / v_in = 6e-4 here with k_n = 1e5 N/m), which the
// spring-dashpot's e does not include.
TEST_P(WallRestitution, SphereDroppedOnPlaneReboundsWithSetRestitution) {
  const double e = GetParam();
  const double kn = 1.0e5;
  const double g = 9.81;
  const Wall floor = Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictionless_law(kn, e));
  const auto [measured, omega_dt] = drop_on_wall(floor, {0, 0, 0.00101}, {0, 0, -1.0}, {0, 0, -g}, e);
  const double m = sphere_mass(0.001, 2500.0);
  const double t_c = std::numbers::pi * std::sqrt(m / kn);
  const double tol = restitution_tolerance(e, omega_dt) + 2.0 * g * t_c / 1.0;
  report("floor e={}: |e_meas - e| = {:.2e} (tol {:.2e})", e, std::fabs(measured - e), tol);
  EXPECT_NEAR(measured, e, tol);
}

// The same law on a finite rectangle, hit on its face and, obliquely, on an edge, where the
// contact normal comes from the closest point on the edge (no gravity: the exact bound applies).
TEST_P(WallRestitution, RectangleFaceAndEdge) {
  const double e = GetParam();
  const double kn = 1.0e4;
  const Wall plate = Wall::rectangle("plate", {0, 0, 0}, {1, 0, 0}, 0.01, {0, 1, 0}, 0.01, frictionless_law(kn, e));
  {
    const auto [measured, omega_dt] = drop_on_wall(plate, {0.002, 0.003, 0.00101}, {0, 0, -1.0}, {}, e);
    report("rectangle face e={}: |e_meas - e| = {:.2e} (tol {:.2e})", e, std::fabs(measured - e),
           restitution_tolerance(e, omega_dt));
    EXPECT_NEAR(measured, e, restitution_tolerance(e, omega_dt)) << "face";
  }
  {
    // Towards the edge x = +0.01 along the bisector of the face and the edge's outer side.
    const Vec3 dir = Vec3{-1, 0, -1} / std::sqrt(2.0);
    const Vec3 start = Vec3{0.01, 0.0, 0.0} - 0.00101 * dir;
    const auto [measured, omega_dt] = drop_on_wall(plate, start, dir * 1.0, {}, e);
    report("rectangle edge e={}: |e_meas - e| = {:.2e} (tol {:.2e})", e, std::fabs(measured - e),
           restitution_tolerance(e, omega_dt));
    EXPECT_NEAR(measured, e, restitution_tolerance(e, omega_dt)) << "edge";
  }
}

INSTANTIATE_TEST_SUITE_P(Collision, WallRestitution, ::testing::Values(0.3, 0.6, 0.9, 1.0));
