// The clump benchmark (issue 39): a settled bed of rigid clumps (2 mm volume-equivalent, random
// orientations) in a W x 0.0182 x 0.06 m box under 50 g, and beside it a settled bed of as many
// free spheres of the members' size, both with the standard problem's law without rolling
// resistance (k_n 1e6 N/m, k_t 5e5 N/m, e 0.5, mu 0.5) and the clumps' time step. Each bed is
// poured as a lattice of grains that falls and settles (--settle steps), then timed over --steps
// steps, --reps times at each thread count; the median is printed:
//   trapdem-clumps shape=dimer bodies=4440 members=8064 threads=1 Mbody-steps/s=1.23 Mmember-steps/s=2.46
//   trapdem-spheres N=8064 threads=1 Mpsteps/s=3.10
//   # threads=1: a member sphere costs 1.26 x a free sphere
// Usage: clumps [--shape dimer|tetrahedral|sub_angular] [--width W] [--steps N] [--settle K]
//               [--reps R] [--threads "1 2"]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dem/rigid/clump_shapes.hpp"
#include "dem/simulation.hpp"

using namespace trapdem;

namespace {

constexpr double kDepth = 0.0182, kHeight = 0.06;  // m
constexpr double kDiameter = 0.002;                // m, volume-equivalent
constexpr double kDensity = 2500.0;                // kg/m^3

struct Options {
  std::string shape = "dimer";
  double width = 0.1;
  long steps = 2000;
  long settle = 80000;  // the top layers land after ~0.015 s (~55 000 steps); then the bed settles
  int reps = 3;
  std::vector<int> threads{1, 2};
};

[[noreturn]] void usage(const char* prog, const std::string& why) {
  std::fprintf(stderr,
               "%s: %s\nusage: %s [--shape dimer|tetrahedral|sub_angular] [--width W] [--steps N] [--settle K] "
               "[--reps R] [--threads \"1 2\"]\n",
               prog, why.c_str(), prog);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "-h" || a == "--help") usage(argv[0], "help");
    if (k + 1 >= argc) usage(argv[0], "option " + a + " needs a value");
    const std::string v = argv[++k];
    auto num = [&](double lo) {
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(x >= lo)) usage(argv[0], a + " " + v + ": expected a number >= " + std::to_string(lo));
      return x;
    };
    if (a == "--shape") o.shape = v;
    else if (a == "--width") o.width = num(0.01);
    else if (a == "--steps") o.steps = long(num(1));
    else if (a == "--settle") o.settle = long(num(0));
    else if (a == "--reps") o.reps = int(num(1));
    else if (a == "--threads") {
      o.threads.clear();
      std::istringstream in(v);
      for (int t; in >> t;) o.threads.push_back(t);
      if (o.threads.empty()) usage(argv[0], "--threads: expected thread counts, \"1 2\"");
    } else usage(argv[0], "unknown option " + a);
  }
  return o;
}

ClumpTemplate shape_of(const std::string& name) {
  if (name == "dimer") return make_clump_template(dimer_members(1.5), "dimer 1.5").scaled_to(kDiameter);
  if (name == "tetrahedral") return make_clump_template(tetrahedral_members(1.0), "tetrahedral").scaled_to(kDiameter);
  if (name == "sub_angular")
    return make_clump_template(sub_angular_members(6, 0.5), "sub-angular 6 x 0.5").scaled_to(kDiameter);
  throw InputError("--shape " + name + ": expected dimer, tetrahedral or sub_angular");
}

ContactLaw bench_law() {
  ContactLaw law;
  law.normal_stiffness = 1.0e6;
  law.tangential_stiffness = 5.0e5;
  law.restitution = 0.5;
  law.static_friction = law.kinetic_friction = 0.5;
  law.rolling_friction = 0.0;
  law.rolling_model = RollingModel::none;
  return law;
}

SimulationSettings box_settings(double width, double dt, double skin) {
  SimulationSettings s;
  s.time_step = dt;
  s.skin = skin;
  s.domain.lower = {0.0, 0.0, 0.0};
  s.domain.upper = {width, kDepth, kHeight};
  return s;
}

void add_box_walls(Simulation& sim, double width) {
  const ContactLaw law = bench_law();
  sim.set_gravity(Vec3{0.0, 0.0, -50.0 * 9.81});
  sim.add_wall(Wall::plane("x0", {0, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x1", {width, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y0", {0, 0, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y1", {0, kDepth, 0}, {0, -1, 0}, law));
  sim.add_wall(Wall::plane("z0", {0, 0, 0}, {0, 0, 1}, law));
}

// Lattice sites `spacing` apart filling the box's lower 90 % (m).
std::vector<Vec3> lattice_sites(double width, double spacing) {
  std::vector<Vec3> sites;
  for (double z = 0.5 * spacing; z < 0.9 * kHeight; z += spacing)
    for (double y = 0.5 * spacing; y + 0.5 * spacing <= kDepth; y += spacing)
      for (double x = 0.5 * spacing; x + 0.5 * spacing <= width; x += spacing) sites.push_back({x, y, z});
  return sites;
}

// Median rate in million grain-steps per second of `reps` timings of `steps` steps.
double median_rate(Simulation& sim, long steps, int reps, double grains) {
  std::vector<double> rates;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    sim.run(steps);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(grains * double(steps) / s * 1e-6);
  }
  std::sort(rates.begin(), rates.end());
  return rates[rates.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const ClumpTemplate shape = shape_of(o.shape);
    const double member_radius = shape.smallest_radius();
    const double skin = 0.2 * kDiameter;  // m, the standard problem's 0.4 mm
    // The clump bed.
    Particles members;
    RigidBodies bodies;
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::int64_t member_id = 1, body_id = 1;
    for (const Vec3& x : lattice_sites(o.width, 2.1 * shape.bounding_radius())) {
      const double u1 = unit(rng), u2 = unit(rng), u3 = unit(rng);
      add_rigid_body(bodies, members, body_id++, member_id, shape, kDensity, x, uniform_orientation(u1, u2, u3));
      member_id += std::int64_t(shape.members.size());
    }
    Simulation clumps(std::move(members), bench_law(), box_settings(o.width, 1.0, skin), std::move(bodies));
    const double dt = 0.2 * clumps.critical_time_step();
    clumps = Simulation(clumps.particles(), bench_law(), box_settings(o.width, dt, skin), clumps.bodies());
    add_box_walls(clumps, o.width);
    // The sphere bed: as many spheres of the members' size.
    Particles spheres;
    std::int64_t sphere_id = 1;
    for (const Vec3& x : lattice_sites(o.width, 2.1 * member_radius)) {
      if (sphere_id > std::int64_t(clumps.particles().size())) break;
      spheres.add(sphere_id++, x, member_radius, kDensity);
    }
    Simulation free_spheres(std::move(spheres), bench_law(), box_settings(o.width, dt, skin));
    add_box_walls(free_spheres, o.width);

    omp_set_num_threads(*std::max_element(o.threads.begin(), o.threads.end()));
    clumps.run(o.settle);
    free_spheres.run(o.settle);
    const double n_bodies = double(clumps.bodies().size()), n_members = double(clumps.particles().size());
    const double n_spheres = double(free_spheres.particles().size());
    std::printf("# %s: %zu bodies of %zu members (member radius %.3g mm), %zu spheres; dt %.4g s; after %ld settling "
                "steps: %.2f contacts per member, %.2f per sphere\n",
                o.shape.c_str(), clumps.bodies().size(), shape.members.size(), member_radius * 1e3,
                free_spheres.particles().size(), dt, o.settle, 2.0 * double(clumps.contact_count()) / n_members,
                2.0 * double(free_spheres.contact_count()) / n_spheres);
    for (const int t : o.threads) {
      omp_set_num_threads(t);
      clumps.run(100);  // warm the threads
      free_spheres.run(100);
      const double member_rate = median_rate(clumps, o.steps, o.reps, n_members);
      const double sphere_rate = median_rate(free_spheres, o.steps, o.reps, n_spheres);
      std::printf("trapdem-clumps shape=%s bodies=%.0f members=%.0f threads=%d Mbody-steps/s=%.3f Mmember-steps/s=%.3f\n",
                  o.shape.c_str(), n_bodies, n_members, t, member_rate * n_bodies / n_members, member_rate);
      std::printf("trapdem-spheres N=%.0f threads=%d Mpsteps/s=%.3f\n", n_spheres, t, sphere_rate);
      std::printf("# threads=%d: a member sphere costs %.2f x a free sphere\n", t, sphere_rate / member_rate);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clumps: %s\n", e.what());
    return 1;
  }
  return 0;
}
