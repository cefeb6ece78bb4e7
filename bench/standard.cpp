// The standard benchmark (the peers' problem, /work/shared/peers/README.md): a settled bed of
// 2 mm spheres in a W x 0.0182 x 0.2 m box under 50 g, read from the LAMMPS packing, run with
// the LIGGGHTS-equivalent contact law (hooke/stiffness, tangential history, rolling epsd2).
//
// Usage: standard --data pack_W0.1.data --width 0.1 --steps 5000 --threads 1 --warmup 300
//                 [--tile K] [--write FILE] [--skin S]
// --tile K lays K copies of the packing side by side along x (a box K W wide, K N particles, x
// walls at 0 and K W only); --write FILE writes the final state as a LAMMPS data file. Together
// they make the paper-scale bed (bench/common.sh: 15 copies of the 20k bed, settled for 20 000
// steps, 13 ms at 50 g): where two copies meet, two flat wall-side layers face each other without
// interlocking and collapse into each other (contacts per particle fell to ~0.4 there within
// 300 steps and the disturbance crossed the copy), so the tiled bed must settle before it is a
// benchmark bed; after 20 000 steps its contacts per particle are 3.6-3.8 everywhere, as the 20k bed's.
// --skin S sets the Verlet skin (m; the problem's is 0.4 mm): a smaller skin lists fewer pairs for
// the sweep to test each step and rebuilds the lists more often (the '#' line gives both).
// Prints one line "trapdem N=19928 threads=1 Mpsteps/s=12.34" and a '#' line with the run's
// sanity figures: contacts per particle, neighbour-list rebuilds in the timed steps and the seconds
// they took (rebuild_s, part of loop_s), the largest overlap, the kinetic energy.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "dem/simulation.hpp"
#include "io/lammps_data.hpp"
#include "standard_problem.hpp"

using namespace trapdem;

namespace {

struct Options {
  std::string data;
  double width = 0.0;
  long steps = 5000;
  int threads = 1;
  long warmup = 300;
  int tile = 1;
  std::string write;
  double skin = 4.0e-4;  // m
};

[[noreturn]] void usage(const char* prog, const std::string& why) {
  std::fprintf(stderr,
               "%s: %s\nusage: %s --data FILE --width W [--steps N] [--threads T] [--warmup K] [--tile C] [--write OUT] [--skin S]\n"
               "  FILE  LAMMPS data file (atom_style sphere) of the settled packing\n"
               "  W     box width in m of FILE (0.1 -> N=19928, 0.4 -> N=80560)\n"
               "  C     copies of the packing along x (0.1 with 15: N=298920, 1.5 m wide)\n"
               "  OUT   LAMMPS data file of the final state\n"
               "  S     Verlet skin in m (the standard problem's: 4e-4)\n",
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
    char* end = nullptr;
    auto num = [&](double lo) {
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(x >= lo)) usage(argv[0], a + " " + v + ": expected a number >= " + std::to_string(lo));
      return x;
    };
    if (a == "--data") o.data = v;
    else if (a == "--width") o.width = num(1e-6);
    else if (a == "--steps") o.steps = static_cast<long>(num(1));
    else if (a == "--threads") o.threads = static_cast<int>(num(1));
    else if (a == "--warmup") o.warmup = static_cast<long>(num(0));
    else if (a == "--tile") o.tile = static_cast<int>(num(1));
    else if (a == "--write") o.write = v;
    else if (a == "--skin") o.skin = num(1e-9);
    else usage(argv[0], "unknown option " + a);
  }
  if (o.data.empty()) usage(argv[0], "--data is required");
  if (o.width <= 0.0) usage(argv[0], "--width is required");
  return o;
}

// `copies` copies of `bed` side by side along x, each shifted by `width` (m), ids renumbered.
Particles tiled_along_x(const Particles& bed, double width, int copies) {
  Particles out;
  out.reserve(bed.size() * std::size_t(copies));
  std::int64_t next_id = 1;
  for (int c = 0; c < copies; ++c)
    for (std::size_t i = 0; i < bed.size(); ++i)
      out.add(next_id++, bed.position[i] + Vec3{c * width, 0.0, 0.0}, bed.radius[i], bed.density(i), bed.velocity[i],
              bed.angular_velocity[i]);
  return out;
}

int run(const Options& o) {
  omp_set_num_threads(o.threads);

  LammpsData data = read_lammps_data(o.data);
  if (std::fabs(data.box_upper.x - o.width) > 1e-9 || std::fabs(data.box_lower.x) > 1e-9)
    throw InputError(o.data + ": box x = [" + std::to_string(data.box_lower.x) + ", " + std::to_string(data.box_upper.x) +
                     "] does not match --width " + std::to_string(o.width));
  if (o.tile > 1) data.particles = tiled_along_x(data.particles, o.width, o.tile);
  const std::size_t n = data.particles.size();
  const double width = o.width * o.tile;  // m

  Simulation sim = standard_problem(std::move(data.particles), width, o.skin);

  sim.run(o.warmup);
  const std::int64_t rebuilds0 = sim.stats().rebuilds;
  const double rebuild_seconds0 = sim.stats().rebuild_seconds;
  const double ke0 = sim.kinetic_energy();
  double max_overlap = 0.0;

  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < o.steps; ++k) {
    sim.step();
    max_overlap = std::max(max_overlap, sim.max_overlap_fraction());
  }
  const auto t1 = std::chrono::steady_clock::now();

  const double seconds = std::chrono::duration<double>(t1 - t0).count();
  const double rate = double(n) * double(o.steps) / seconds / 1e6;
  const double contacts_per_particle = 2.0 * double(sim.contact_count()) / double(n);
  std::printf("trapdem N=%zu threads=%d Mpsteps/s=%.3f\n", n, o.threads, rate);
  const double listed_per_particle = double(sim.pairs().size()) / double(n);  // half pairs
  std::printf("# loop_s=%.3f steps=%ld warmup=%ld contacts/particle=%.4f rebuilds=%lld rebuild_s=%.3f "
              "max_overlap=%.3f%% ke_start=%.4g J ke_end=%.4g J skin=%.3g m listed_pairs/particle=%.3f\n",
              seconds, o.steps, o.warmup, contacts_per_particle,
              static_cast<long long>(sim.stats().rebuilds - rebuilds0), sim.stats().rebuild_seconds - rebuild_seconds0,
              100.0 * max_overlap, ke0, sim.kinetic_energy(), o.skin, listed_per_particle);
  // The code and the CPU each figure belongs to (bench/RESULTS.md names both for every result).
  std::printf("# trapdem %s, on %s\n", describe_build().c_str(), describe_cpu().c_str());
  if (!o.write.empty()) {
    LammpsWriteOptions w;
    w.title = "trapdem bench bed: " + std::to_string(o.tile) + " x " + o.data + ", settled " +
              std::to_string(o.warmup + o.steps) + " steps at 50 g";
    write_lammps_data(o.write, sim.particles(), Vec3{0.0, 0.0, 0.0}, Vec3{width, kStandardDepth, kStandardHeight}, w);
  }
  if (!std::isfinite(rate) || contacts_per_particle < 1.0)
    throw SimulationError("implausible run: contacts per particle " + std::to_string(contacts_per_particle) +
                          " (a settled bed has ~3.6); is the data file a settled packing?");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "standard: error: %s\n", e.what());
    return 1;
  }
}
