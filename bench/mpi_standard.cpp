// The standard benchmark on MPI ranks (bench/run-mpi.sh): the bed of bench/standard.cpp split in
// slabs along x (src/parallel), R ranks x T OpenMP threads.
//
// Usage: mpirun -np R mpi_standard --data pack_W0.1.data --width 0.1 --steps 5000 --threads 1 --warmup 300
// Prints (rank 0) one line "trapdem N=19928 ranks=2 threads=1 Mpsteps/s=12.34", a '#' line with
// contacts per particle and rebuilds, and per rank a '# halo' line: owned particles, ghosts held
// per step and the wall clock of the exchanges per step (SimulationStats: the ghosts' positions
// out, their forces back, the wall loads and the step's reductions, outside rebuilds), the
// measured inputs of the weak-scaling model in bench/RESULTS.md.
#include <mpi.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dem/simulation.hpp"
#include "io/lammps_data.hpp"
#include "parallel/slab_decomposition.hpp"
#include "standard_problem.hpp"

using namespace trapdem;

namespace {

struct Options {
  std::string data;
  double width = 0.0;
  long steps = 5000, warmup = 300;
  int threads = 1;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string a = argv[k], v = argv[k + 1];
    if (a == "--data") o.data = v;
    else if (a == "--width") o.width = std::atof(v.c_str());
    else if (a == "--steps") o.steps = std::atol(v.c_str());
    else if (a == "--warmup") o.warmup = std::atol(v.c_str());
    else if (a == "--threads") o.threads = std::atoi(v.c_str());
    else throw InputError("unknown option " + a + " (--data FILE --width W --steps N --warmup K --threads T)");
  }
  if (o.data.empty() || !(o.width > 0.0) || o.steps < 1 || o.warmup < 0 || o.threads < 1)
    throw InputError("usage: mpi_standard --data FILE --width W [--steps N] [--warmup K] [--threads T]");
  return o;
}

int run(const Options& o, int rank, int ranks) {
  omp_set_num_threads(o.threads);
  LammpsData data = read_lammps_data(o.data);
  const std::size_t n = data.particles.size();
  Simulation sim = standard_problem(std::move(data.particles), o.width);
  decompose_in_slabs(sim, MPI_COMM_WORLD);
  sim.run(o.warmup);
  const SimulationStats before = sim.stats();
  MPI_Barrier(MPI_COMM_WORLD);
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(o.steps);
  MPI_Barrier(MPI_COMM_WORLD);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const SimulationStats& after = sim.stats();
  const double contacts_per_particle = 2.0 * double(sim.contact_count()) / double(n);  // collective
  const std::vector<double> mine = {double(sim.owned_count()),
                                    double(after.ghost_steps - before.ghost_steps) / double(o.steps),
                                    (after.exchange_seconds - before.exchange_seconds) / double(o.steps),
                                    after.rebuild_seconds - before.rebuild_seconds};
  std::vector<double> all(mine.size() * std::size_t(ranks));
  MPI_Gather(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), int(mine.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (rank != 0) return 0;
  const double rate = double(n) * double(o.steps) / seconds / 1e6;
  std::printf("trapdem N=%zu ranks=%d threads=%d Mpsteps/s=%.3f\n", n, ranks, o.threads, rate);
  std::printf("# loop_s=%.3f steps=%ld warmup=%ld contacts/particle=%.4f rebuilds=%lld\n", seconds, o.steps, o.warmup,
              contacts_per_particle, static_cast<long long>(after.rebuilds - before.rebuilds));
  for (int r = 0; r < ranks; ++r) {
    const double* v = all.data() + mine.size() * std::size_t(r);
    std::printf("# halo rank=%d owned=%.0f ghosts/step=%.1f exchange_us/step=%.2f rebuild_s=%.3f\n", r, v[0], v[1],
                v[2] * 1e6, v[3]);
  }
  if (!std::isfinite(rate) || contacts_per_particle < 1.0)
    throw SimulationError("implausible run: contacts per particle " + std::to_string(contacts_per_particle));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int code = 0;
  try {
    code = run(parse(argc, argv), rank, ranks);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mpi_standard (rank %d): error: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return code;
}
