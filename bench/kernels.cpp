// Micro-benchmarks of the engine's two hot spots:
//   * ContactEvaluator::evaluate(): the contact law on a batch of prepared contacts (no neighbour access), per
//     rolling model (0 none, 1 constant torque, 2 elastic-plastic EPSD as in the standard benchmark);
//   * the neighbour-list build: sort_into_cells() + build_pairs() on a random (jittered lattice)
//     packing of 2 mm spheres with the standard benchmark's skin, for N and the OpenMP thread count;
//   * the whole list rebuild of the engine (Simulation::rebuild_lists: the histories archived by
//     particle id, the cell sort, the re-order, the pair and wall lists, the histories restored) on
//     the same packing pressed into contact (six touching neighbours a particle, each with a history).
// Run: build/bench/kernels [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dem/contact/law.hpp"
#include "dem/cell_sort.hpp"
#include "dem/pair_list.hpp"
#include "dem/particles.hpp"
#include "dem/simulation.hpp"
#include "standard_problem.hpp"

using namespace trapdem;

namespace {

constexpr double kRadius = 0.001, kDensity = 2500.0, kSkin = 4.0e-4;

struct ContactCase {
  Vec3 normal, relative_velocity, w_i, w_j;
  double overlap;
  ContactHistory history;
};

std::vector<ContactCase> make_contacts(std::size_t count) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  std::vector<ContactCase> cases(count);
  for (ContactCase& c : cases) {
    Vec3 n{u(rng), u(rng), u(rng)};
    c.normal = n / norm(n);
    c.overlap = 2e-5 * u01(rng);  // a settled bed under 50 g: overlaps of a few micrometres
    c.relative_velocity = 1e-3 * Vec3{u(rng), u(rng), u(rng)};
    c.w_i = 0.5 * Vec3{u(rng), u(rng), u(rng)};
    c.w_j = 0.5 * Vec3{u(rng), u(rng), u(rng)};
    if (u01(rng) < 0.8) {  // most contacts carry history from earlier steps
      c.history.tangential_spring = 1e-6 * Vec3{u(rng), u(rng), u(rng)};
      c.history.rolling_spring = 1e-6 * Vec3{u(rng), u(rng), u(rng)};
      c.history.flags = ContactHistory::kTouching | (u01(rng) < 0.1 ? ContactHistory::kSliding : 0u);
    }
  }
  return cases;
}

ContactLaw standard_law(int rolling) {
  ContactLaw law;
  law.normal_stiffness = 1.0e6;
  law.tangential_stiffness = 5.0e5;
  law.restitution = 0.9;
  law.static_friction = law.kinetic_friction = 0.5;
  law.rolling_friction = rolling ? 0.2 : 0.0;
  law.rolling_model = static_cast<RollingModel>(rolling);
  law.rolling_stiffness = RollingStiffness::tangential;
  law.lever_arm = RollingLeverArm::effective_radius;
  law.rolling_damping = 0.0;
  return law;
}

// The law's instance for standard_law(rolling): what law_choices() gives for it.
constexpr LawChoices kStandardChoices[] = {
    LawChoices{},
    LawChoices{.rolling = RollingModel::constant_torque, .lever_arm = RollingLeverArm::effective_radius},
    LawChoices{.rolling = RollingModel::elastic_plastic,
               .lever_arm = RollingLeverArm::effective_radius,
               .rolling_stiffness = RollingStiffness::tangential},
};

template <LawChoices kLaw>
void contact_force_loop(benchmark::State& state, const LawParams& c, std::vector<ContactCase>& cases) {
  const double m = kDensity * 4.0 / 3.0 * M_PI * kRadius * kRadius * kRadius;
  const double inertia = 0.4 * m * kRadius * kRadius;
  ContactBodies b;
  b.effective_mass = 0.5 * m;
  b.effective_radius = 0.5 * kRadius;
  b.lever = 0.5 * kRadius;
  b.rolling_inertia = 0.5 * (inertia + m * kRadius * kRadius);
  b.spin_inertia = 0.5 * inertia;
  const double dt = 6.472e-7;
  for (auto _ : state) {
    Vec3 sum{};
    for (ContactCase& k : cases) {
      b.arm_i = b.arm_j = kRadius - 0.5 * k.overlap;
      const ContactForce f =
          ContactEvaluator<kLaw>::evaluate(c, b, k.normal, k.overlap, k.relative_velocity, k.w_i, k.w_j, k.history, dt);
      sum += f.force + f.rolling_torque;
    }
    benchmark::DoNotOptimize(sum);
  }
}

void BM_ContactForce(benchmark::State& state) {
  const int rolling = static_cast<int>(state.range(0));
  const ContactLaw law = standard_law(rolling);
  if (!(law_choices(law) == kStandardChoices[rolling])) {
    state.SkipWithError("the standard law's choices differ from the instance compiled for it");
    return;
  }
  const LawParams c = law_params(law, law);
  std::vector<ContactCase> cases = make_contacts(4096);
  if (rolling == 0) contact_force_loop<kStandardChoices[0]>(state, c, cases);
  if (rolling == 1) contact_force_loop<kStandardChoices[1]>(state, c, cases);
  if (rolling == 2) contact_force_loop<kStandardChoices[2]>(state, c, cases);
  state.SetItemsProcessed(state.iterations() * std::int64_t(cases.size()));
  state.SetLabel(rolling == 0 ? "no rolling" : (rolling == 1 ? "constant torque" : "EPSD"));
}
BENCHMARK(BM_ContactForce)->Arg(0)->Arg(1)->Arg(2);

// A loose random packing: a simple-cubic lattice of spacing 2.05 mm, jittered by +-0.02 mm, in a
// box W x 0.0182 x 0.094 m (the settled bed's size), shuffled, then put in cell order as the
// engine keeps it (it re-orders particles at every rebuild).
struct Packing {
  Particles particles;
  Domain domain;
};

Packing make_packing(std::size_t n_target, double spacing = 2.05e-3) {
  const double depth = 0.0182, height = 0.094;
  const int ny = static_cast<int>(depth / spacing), nz = static_cast<int>(height / spacing);
  const int nx = static_cast<int>(std::ceil(double(n_target) / (ny * nz)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-2e-5, 2e-5);
  std::vector<Vec3> xs;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz && xs.size() < n_target; ++k)
        xs.push_back({(i + 0.5) * spacing + jitter(rng), (j + 0.5) * spacing + jitter(rng), (k + 0.5) * spacing + jitter(rng)});
  std::shuffle(xs.begin(), xs.end(), rng);
  Packing pk;
  pk.domain.lower = {0, 0, 0};
  pk.domain.upper = {nx * spacing, depth, 0.2};
  for (std::size_t i = 0; i < xs.size(); ++i) pk.particles.add(std::int64_t(i + 1), xs[i], kRadius, kDensity);
  const CellSort cells = sort_into_cells(pk.particles.position, pk.domain, 2 * kRadius + kSkin);
  pk.particles.permute(cells.order);
  return pk;
}

void BM_NeighbourBuild(benchmark::State& state) {
  const Packing pk = make_packing(static_cast<std::size_t>(state.range(0)));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  PairList pairs;
  for (auto _ : state) {
    const CellSort cells = sort_into_cells(pk.particles.position, pk.domain, 2 * kRadius + kSkin);
    build_pairs(pk.particles, cells, pk.domain, kSkin, pairs);
    benchmark::DoNotOptimize(pairs.partner.data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(pk.particles.size()));
  state.counters["pairs/particle"] = double(pairs.size()) / double(pk.particles.size());
}
BENCHMARK(BM_NeighbourBuild)->Args({20000, 1})->Args({20000, 2})->Args({80000, 1})->Args({80000, 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SortIntoCells(benchmark::State& state) {
  const Packing pk = make_packing(static_cast<std::size_t>(state.range(0)));
  omp_set_num_threads(1);
  for (auto _ : state) {
    CellSort cells = sort_into_cells(pk.particles.position, pk.domain, 2 * kRadius + kSkin);
    benchmark::DoNotOptimize(cells.order.data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(pk.particles.size()));
}
BENCHMARK(BM_SortIntoCells)->Arg(20000)->Arg(80000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The engine's rebuild on a bed in contact: the lattice at 1.995 mm (5 um overlaps), so that every
// rebuild archives and restores ~3 histories a particle; the standard problem's law and walls, no
// gravity. Each iteration invalidates the lists and steps once; the rebuild's own wall clock
// (SimulationStats::rebuild_seconds) is the counter `rebuild_ms`, the whole step's the time.
void BM_ListRebuild(benchmark::State& state) {
  Packing pk = make_packing(static_cast<std::size_t>(state.range(0)), 1.995e-3);
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const double width = pk.domain.upper.x;
  Simulation sim = standard_problem(std::move(pk.particles), width);
  sim.set_gravity(Vec3{0.0, 0.0, 0.0});
  sim.step();  // the contacts and their histories
  const double before = sim.stats().rebuild_seconds;
  for (auto _ : state) {
    sim.particles_mutable();  // the lists invalid: the next step rebuilds them
    sim.step();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(sim.particles().size()));
  state.counters["rebuild_ms"] = 1e3 * (sim.stats().rebuild_seconds - before) / double(state.iterations());
  state.counters["contacts/particle"] = double(sim.contact_count()) / double(sim.particles().size());
}
// A fixed count of iterations: the bed relaxes from step to step, so every binary times the same steps.
BENCHMARK(BM_ListRebuild)->Args({80000, 1})->Args({80000, 2})->Args({300000, 1})->Args({300000, 2})
    ->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
