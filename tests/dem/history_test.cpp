// Contact history (tangential and rolling springs, sliding flags) must survive Verlet-list
// rebuilds and the spatial re-ordering of particles: it is archived by particle id and restored.
// A run that rebuilds (and re-orders) every few steps must follow the run that never rebuilds.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

struct Outcome {
  std::map<std::int64_t, Vec3> position, spin;
  std::int64_t rebuilds;
  std::size_t sliding_wall_contacts = 0, touching_pairs = 0;
};

// A pyramid of four spheres (three on the floor, one on top, held by friction) on a slope:
// gravity tilted by atan(0.3) along x. The base spheres roll and slide on the floor; the top one
// rests on them through sticking tangential springs and EPSD rolling springs, so losing any of
// that history would jolt it. Ids are given in reverse spatial order so re-ordering moves them.
Outcome run_pyramid(double skin, int reorder_every) {
  const double r = 0.001;
  ContactLaw law = sliding_rolling_law(1.0e4, 0.3, 0.6, 0.5, 0.1);  // mu_s, mu_k, mu_r
  ContactLaw floor_law = law;
  floor_law.static_friction = floor_law.kinetic_friction = 0.2;  // base slides on the floor
  const double h = r * std::sqrt(8.0 / 3.0) * 0.999;              // top sphere slightly pressed in
  Particles p;
  p.add(4, {r * std::sqrt(3.0) / 3.0, 0.0, r + h}, r, 2500.0);  // top, over the base's centroid
  p.add(3, {0.0, -r, r}, r, 2500.0);
  p.add(2, {0.0, r, r}, r, 2500.0);
  p.add(1, {r * std::sqrt(3.0), 0.0, r}, r, 2500.0);
  SimulationSettings s;
  s.domain = box(0.1);
  s.skin = skin;
  s.reorder_every = reorder_every;
  s.time_step_fraction = 0.2;
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, floor_law));
  const double angle = std::atan(0.3);
  sim.set_gravity(Vec3{9.81 * std::sin(angle), 0.0, -9.81 * std::cos(angle)});
  sim.run(4000);
  Outcome out;
  const Particles& q = sim.particles();
  for (std::size_t i = 0; i < q.size(); ++i) {
    out.position[q.id[i]] = q.position[i];
    out.spin[q.id[i]] = q.angular_velocity[i];
  }
  out.rebuilds = sim.stats().rebuilds;
  // std::as_const: on a non-const Simulation the name resolves to the private step kernel.
  for (const ContactHistory& hist : sim.wall_candidates().history) out.sliding_wall_contacts += hist.sliding();
  out.touching_pairs = sim.contact_count();
  return out;
}

}  // namespace

TEST(ContactHistory, SurvivesRebuildsAndReordering) {
  const Outcome steady = run_pyramid(0.05, 1);        // 50 mm skin: built once, never rebuilt
  const Outcome churn = run_pyramid(2e-6, 1);         // 2 um skin: rebuilt (and re-ordered) every few steps
  ASSERT_EQ(steady.rebuilds, 1);
  ASSERT_GT(churn.rebuilds, 200);
  EXPECT_GE(churn.touching_pairs, 2u);                // the top sphere still rides on the base...
  EXPECT_EQ(steady.touching_pairs, churn.touching_pairs);
  double travel = 0.0, worst = 0.0, worst_spin = 0.0, spin_scale = 0.0;
  for (const auto& [id, x] : steady.position) {
    travel = std::max(travel, std::fabs(x.x));
    worst = std::max(worst, norm(churn.position.at(id) - x));
    worst_spin = std::max(worst_spin, norm(churn.spin.at(id) - steady.spin.at(id)));
    spin_scale = std::max(spin_scale, norm(steady.spin.at(id)));
  }
  // The two runs differ only in the order of floating-point sums (particles are re-ordered), so
  // they agree to round-off amplified over 4000 steps: 1e-12 m here (1e-9 of r). Losing the
  // history resets springs carrying ~mu |F_n| and moves the spheres by ~F / k_t ~ 1e-8 m at once.
  report("history: travel {:.2e} m, {} rebuilds; max position difference {:.1e} m (tol 1e-12), spin difference "
         "{:.1e} of max spin (tol 1e-9)",
         travel, churn.rebuilds, worst, worst_spin / spin_scale);
  EXPECT_GT(travel, 1e-4);  // ...and moved down the slope well beyond the skin
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_spin, 1e-9 * spin_scale);
}
