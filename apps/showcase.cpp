// The engine's showcase: a polydisperse packing settles in a box under gravity, and the floor
// carries its weight. What `make demo` runs until the trapdoor experiment exists.
#include "showcase.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "dem/packing.hpp"
#include "dem/thread_scope.hpp"
#include "dem/simulation.hpp"

namespace trapdem::app {

int run_showcase(const ShowcaseOptions& o) {
  const ThreadScope threads(o.threads);
  const double width = 0.1, depth = 0.0182, height = 0.3;  // m, a slab like the paper's strongbox
  LatticeSpec spec;
  spec.lower = {0, 0, 0};
  spec.upper = {width, depth, height};
  spec.radius_min = 0.0009;
  spec.radius_max = 0.0011;
  spec.density = 2500.0;
  spec.max_count = std::size_t(o.particles);
  Particles particles = jittered_lattice(spec);

  ContactLaw law;
  law.normal_stiffness = 2.0e4;  // N/m: overlaps stay below 0.1 % of the radius at 1 g
  law.tangential_stiffness = 1.0e4;
  law.restitution = 0.5;
  law.static_friction = law.kinetic_friction = 0.5;
  law.rolling_friction = 0.1;
  law.rolling_model = RollingModel::elastic_plastic;

  SimulationSettings settings;
  settings.domain.lower = {-0.01, -0.01, -0.01};
  settings.domain.upper = {width + 0.01, depth + 0.01, height + 0.05};
  settings.time_step_fraction = 0.2;
  const std::size_t n = particles.size();
  const double weight = particles.total_mass() * 9.81;
  Simulation sim(std::move(particles), law, settings);
  sim.set_gravity(Vec3{0, 0, -9.81});
  const auto floor = sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("left", {0, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("right", {width, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("back", {0, 0, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("front", {0, depth, 0}, {0, -1, 0}, law));

  fmt::print("trapdem showcase: {} spheres (r = 0.9-1.1 mm) settle in a {:.0f} x {:.1f} mm box under 1 g\n", n,
             width * 1e3, depth * 1e3);
  fmt::print("  time step {:.3g} s ({:.2f} of the critical {:.3g} s), {} threads\n", sim.time_step(),
             settings.time_step_fraction, sim.critical_time_step(), omp_get_max_threads());
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t chunk = 5000, max_steps = 400000;
  double ratio = 1.0;
  while (sim.step_count() < max_steps) {
    sim.run(chunk);
    // Translational only: a sphere spinning about its contact normal meets no resistance in
    // this model (no twisting torque), so rotational energy need not vanish at rest.
    ratio = sim.translational_kinetic_energy() / sim.potential_energy();
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("  step {:7d}  t = {:6.3f} s  translational kinetic/potential energy = {:9.2e}  {:6.2f} M particle-steps/s\n",
               sim.step_count(), sim.time(), ratio, double(n) * sim.step_count() / secs / 1e6);
    std::fflush(stdout);
    if (sim.time() > 0.2 && ratio < 1e-8) break;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double carried = -sim.walls()[floor].force.z;
  double all_walls = 0.0;
  for (const Wall& w : sim.walls()) all_walls -= w.force.z;
  fmt::print("\nmeasured:\n");
  fmt::print("  particles            {}\n", n);
  fmt::print("  steps                {} ({:.3f} s simulated, {} neighbour-list rebuilds)\n", sim.step_count(),
             sim.time(), sim.stats().rebuilds);
  fmt::print("  particle-steps/s     {:.2f} M ({:.1f} s wall clock)\n", double(n) * sim.step_count() / secs / 1e6, secs);
  fmt::print("  contacts/particle    {:.2f}\n", 2.0 * double(sim.contact_count()) / double(n));
  fmt::print("  floor carries        {:.6g} N\n", carried);
  fmt::print("  all walls carry      {:.6g} N (the side walls take the rest by friction)\n", all_walls);
  fmt::print("  particles' weight    {:.6g} N  (floor / weight = {:.5f}, all walls / weight = {:.6f})\n", weight,
             carried / weight, all_walls / weight);
  return 0;
}

}  // namespace trapdem::app
