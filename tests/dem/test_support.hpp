#pragma once
// Small helpers shared by the engine's analytic tests (tests/dem/*_test.cpp).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "dem/simulation.hpp"

namespace trapdem::testing_support {

// Prints a measured error next to its tolerance when TRAPDEM_TEST_REPORT is set in the
// environment (for reviewing how much margin each check has); silent otherwise.
template <class... Args>
void report(fmt::format_string<Args...> format, Args&&... args) {
  if (std::getenv("TRAPDEM_TEST_REPORT")) fmt::print("    [report] {}\n", fmt::format(format, std::forward<Args>(args)...));
}

// A bounded box [-half, half]^3 (m) with no periodic axis.
inline Domain box(double half) {
  Domain d;
  d.lower = {-half, -half, -half};
  d.upper = {half, half, half};
  return d;
}

inline double sphere_mass(double radius, double density) {
  return density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

// A linear spring-dashpot law with the given restitution; friction and rolling off unless set later.
inline ContactLaw frictionless_law(double kn, double restitution) {
  ContactLaw law;
  law.normal_stiffness = kn;
  law.tangential_stiffness = 0.5 * kn;
  law.restitution = restitution;
  law.static_friction = 0.0;
  law.kinetic_friction = 0.0;
  law.rolling_friction = 0.0;
  law.rolling_model = RollingModel::none;
  return law;
}

// frictionless_law(kn, e) with Coulomb friction (mu_s, mu_k) and EPSD rolling resistance mu_r
// (Ai et al. 2011's default dashpot): every sub-model of the law in play.
inline ContactLaw sliding_rolling_law(double kn, double restitution, double mu_s, double mu_k, double mu_r) {
  ContactLaw law = frictionless_law(kn, restitution);
  law.static_friction = mu_s;
  law.kinetic_friction = mu_k;
  law.rolling_friction = mu_r;
  law.rolling_model = RollingModel::elastic_plastic;
  return law;
}

// Brute-force O(N^2) reference for the pair list: every pair (i < j) closer than r_i + r_j + skin
// (minimum image on periodic axes).
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Particles& p, const Domain& domain,
                                                                              double skin) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      const Vec3 d = domain.minimum_image(p.position[i] - p.position[j]);
      const double reach = p.radius[i] + p.radius[j] + skin;
      if (norm2(d) < reach * reach) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

// Deterministic pseudo-random numbers (splitmix64) so that tests do not depend on a library's
// distribution implementation.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t state_;
};

// Linear springs with friction and EPSD rolling resistance: pairs carry tangential and rolling springs.
inline ContactLaw frictional_rolling_law() {
  ContactLaw law;
  law.normal_stiffness = 2.0e4;
  law.tangential_stiffness = 1.0e4;
  law.restitution = 0.5;
  law.static_friction = 0.4;
  law.kinetic_friction = 0.3;
  law.rolling_friction = 0.1;
  law.rolling_model = RollingModel::elastic_plastic;
  law.lever_arm = RollingLeverArm::effective_radius;
  law.rolling_damping = 0.3;
  return law;
}

// A dense polydisperse packing: nx x ny x nz spheres on a cubic lattice of `spacing` (m), each
// centre jittered by +-0.05 mm, radii 0.95-1.07 mm (neighbours at 2 mm overlap), ids 1..n in
// lattice order, velocities `drift` + +-0.05 m/s and spins +-50 rad/s: every contact has a
// relative velocity and a rolling motion, so every sub-model of the law is exercised.
inline Particles jittered_lattice(std::uint64_t seed, int nx, int ny, int nz, double spacing, double density,
                                  const Vec3& drift = Vec3{0.0, 0.0, 0.0}) {
  Rng rng(seed);
  Particles p;
  std::int64_t id = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double r = rng.uniform(0.95e-3, 1.07e-3);
        const Vec3 x{(i + 0.5) * spacing + rng.uniform(-5e-5, 5e-5), (j + 0.5) * spacing + rng.uniform(-5e-5, 5e-5),
                     0.96e-3 + k * spacing + rng.uniform(-5e-5, 5e-5)};
        const Vec3 v{drift.x + rng.uniform(-0.05, 0.05), drift.y + rng.uniform(-0.05, 0.05),
                     drift.z + rng.uniform(-0.05, 0.05)};
        p.add(id++, x, r, density, v, {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)});
      }
  return p;
}

}  // namespace trapdem::testing_support
