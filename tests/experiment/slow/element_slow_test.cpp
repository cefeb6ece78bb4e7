// The virtual element test's physics at large strain (slow: specimens of 1000 spheres sheared to
// 15-25 % axial strain; about a quarter of an hour with ctest -j2). In tests/experiment/slow: program
// test_experiment_slow, label slow, excluded from `make test` and run by `make test-slow`.
//
// 1. Frictionless spheres still have a macroscopic friction: Peyneau & Roux (2008), "Frictionless
//    bead packs have macroscopic friction, but no dilatancy", Phys. Rev. E 78, 011307, find an
//    internal friction angle of 5.76 deg (friction coefficient mu* = tau / sigma_n ~ 0.100) for
//    nearly rigid frictionless beads in simple shear in the quasi-static limit, no dilatancy, and
//    mu* rising as a power of the inertial number I. What is comparable: (a) simple shear and the
//    biaxial test are both plane strain, and with coaxial stress and strain rate and no dilatancy
//    (psi = 0) the shear plane is a plane of zero extension, on which tau / sigma_n =
//    sin phi cos psi / (1 - sin phi sin psi) = sin phi (Davis 1968): so mu* is compared with the
//    biaxial test's sin phi' = (sigma_1 - sigma_3) / (sigma_1 + sigma_3), not with tan phi' nor with
//    a triaxial test's angle (Lade-Duncan-like yield, Peyneau & Roux 2008b, PRE 78 041307);
//    (b) their value is the limit I -> 0, ours are at finite I: the test shears at two rates and
//    extrapolates. docs/element.md gives the runs behind the tolerances.
// 2. The critical-state angle grows with the sliding friction mu (0.05, 0.15, 0.3; no rolling
//    resistance; above ~0.3 it saturates) and with the rolling resistance mu_r at mu = 0.3 (0, 0.1,
//    0.3): each step by more than the rows' scatter of phi'_cs over the last 5 % of strain. Goncu & Luding (2013, Acta
//    Geotechnica 8, 629-643) show the first trend (rising, then saturating above mu ~ 0.5), Estrada
//    et al. (2011, Phys. Rev. E 84, 011306) the second.
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../element_test_config.hpp"
#include "experiment/element_config.hpp"
#include "experiment/element_test.hpp"
#include "io/config.hpp"

namespace trapdem {
namespace {

// 2 mm beads on the presets' spring, 1000 of them (docs/element.md: phi'_cs scatters by about a
// degree between seeds at this size). Sheared at I = 2e-3: by the mu(I) rule (Jop et al. 2006,
// mu(I) - mu_s ~ (mu_2 - mu_s) I / I_0 = 0.26 I / 0.28) that adds ~0.1 deg to phi'_cs.
SpecimenResult compute_critical_state(double mu, double mu_r) {
  const std::string text = element_test_config("element-slow", mu, mu_r) +
                           "particles = 1000\n"
                           "max_axial_strain = 0.25\n"
                           "inertial_number = 2e-3\n";
  Config c = Config::parse(text, "element-slow.toml");
  const ElementSetup setup = read_element_setup(c);
  // The loose specimen reaches the critical state without a peak to cross: the cheaper one.
  ElementSpecimen sp = prepare_specimen(setup, Packing::loose, 50e3);
  SpecimenResult r = shear_specimen(sp, setup);
  std::fprintf(stderr, "mu %.2f mu_r %.2f: phi'_cs %.2f +- %.2f deg, solid fraction %.4f, final eps_v %.4f\n", mu,
               mu_r, r.phi_cs, r.phi_cs_scatter, r.isotropic.solid_fraction, r.rows.back().volumetric_strain);
  return r;
}

// Each (mu, mu_r) once per program: the mu = 0.3, mu_r = 0 specimen serves both trends.
const SpecimenResult& loose_critical_state(double mu, double mu_r) {
  static std::map<std::pair<double, double>, SpecimenResult> done;
  const auto key = std::make_pair(mu, mu_r);
  auto it = done.find(key);
  if (it == done.end()) it = done.emplace(key, compute_critical_state(mu, mu_r)).first;
  return it->second;
}

// The frictionless loose specimen (1000 spheres) sheared to 15 % at inertial number `inertial`:
// mean sin phi over rows 5-15 % (the frictionless specimens reach their steady state by 3-4 %) and
// its standard error from the means of four blocks of consecutive rows (the rows are correlated
// over about 1 %: their own standard deviation, ~0.025, would understate the error).
struct SteadyFriction {
  double sin_phi = 0.0, error = 0.0, inertial = 0.0, final_volumetric_strain = 0.0, max_lateral_error = 0.0;
};

SteadyFriction frictionless_steady_state(double inertial) {
  const std::string text = element_test_config("element-frictionless", 0.0, 0.0) +
                           fmt::format("particles = 1000\nmax_axial_strain = 0.15\ncritical_state_window = 0.10\n"
                                       "inertial_number = {}\n",
                                       inertial);
  Config c = Config::parse(text, "element-frictionless.toml");
  const ElementSetup setup = read_element_setup(c);
  ElementSpecimen sp = prepare_specimen(setup, Packing::loose, 50e3);
  const SpecimenResult r = shear_specimen(sp, setup);
  std::vector<double> window;
  double inertial_sum = 0.0;
  for (const ElementRow& row : r.rows)
    if (row.axial_strain >= 0.05) {
      window.push_back(row.sin_phi);
      inertial_sum += row.inertial_number;
    }
  SteadyFriction f;
  const std::size_t n = window.size(), block = n / 4;
  double mean = 0.0, blocks[4] = {};
  for (std::size_t k = 0; k < n; ++k) mean += window[k] / double(n);
  for (int b = 0; b < 4; ++b) {
    for (std::size_t k = b * block; k < (b + 1) * block; ++k) blocks[b] += window[k] / double(block);
  }
  const double block_mean = (blocks[0] + blocks[1] + blocks[2] + blocks[3]) / 4.0;
  double v = 0.0;
  for (double x : blocks) v += (x - block_mean) * (x - block_mean);
  f.sin_phi = mean;
  f.error = std::sqrt(v / 3.0 / 4.0);
  f.inertial = inertial_sum / double(n);  // at the mean stress of the rows
  f.final_volumetric_strain = r.rows.back().volumetric_strain;
  f.max_lateral_error = r.max_lateral_error;
  std::fprintf(stderr, "frictionless, I %.3g: sin phi %.4f +- %.4f (%.2f deg), final eps_v %.4f, lateral within %.4f\n",
               f.inertial, f.sin_phi, f.error, std::asin(f.sin_phi) * 180.0 / std::numbers::pi,
               f.final_volumetric_strain, f.max_lateral_error);
  return f;
}

TEST(ElementSlow, FrictionlessSpheresApproachThePublishedQuasiStaticFriction) {
  const double published = 0.100;  // mu* = sin phi' in the quasi-static limit (5.76 deg), see the top
  const SteadyFriction fast = frictionless_steady_state(1e-3);
  const SteadyFriction slow = frictionless_steady_state(2.5e-4);
  for (const SteadyFriction& f : {fast, slow}) {
    // No dilatancy: the volume stays within a few tenths of a per cent (docs/element.md: |eps_v| <= 0.6 %).
    EXPECT_LT(std::fabs(f.final_volumetric_strain), 0.01);
    EXPECT_LT(f.max_lateral_error, 0.01);
  }
  // The rate adds friction: the slower shear is not stronger beyond the noise.
  const double noise = std::hypot(fast.error, slow.error);
  EXPECT_LT(slow.sin_phi, fast.sin_phi + 2.0 * noise);
  // The limit I -> 0 of mu(I) = mu0 + a I^alpha through the two rates. Four rates (2e-3 to 2.5e-4,
  // docs/element.md) do not fix alpha: 0.25 to 1 fit alike (chi^2 0.43-0.71 for 2 degrees of
  // freedom). So the published limit must lie within two standard errors of the extrapolation for
  // some alpha in that range. A consistency check, and a weak one: the extrapolation multiplies the
  // noise by 1 / (1 - r) (3.4 at alpha = 0.25), so it fails only when both rates give about the
  // same friction above ~0.19 (the rate then not what separates us from the published value).
  bool consistent = false;
  std::string tried;
  for (double alpha : {0.25, 0.4, 0.5, 0.75, 1.0}) {
    const double r = std::pow(slow.inertial / fast.inertial, alpha);
    const double mu0 = (slow.sin_phi - r * fast.sin_phi) / (1.0 - r);
    const double error = std::hypot(slow.error, r * fast.error) / (1.0 - r);
    consistent = consistent || std::fabs(mu0 - published) < 2.0 * error;
    tried += fmt::format(" alpha {}: {:.3f} +- {:.3f};", alpha, mu0, error);
  }
  EXPECT_TRUE(consistent) << "extrapolated sin phi' at I -> 0:" << tried << " published " << published;
}

TEST(ElementSlow, CriticalStateAngleGrowsWithSlidingFriction) {
  // Below the saturation: mu 0.1, 0.3, 0.6 gave 15.4, 20.5, 20.5 deg (0.3 to 0.6 within the scatter).
  const SpecimenResult& low = loose_critical_state(0.05, 0.0);
  const SpecimenResult& mid = loose_critical_state(0.15, 0.0);
  const SpecimenResult& high = loose_critical_state(0.3, 0.0);
  EXPECT_GT(mid.phi_cs - low.phi_cs, std::max(low.phi_cs_scatter, mid.phi_cs_scatter));
  EXPECT_GT(high.phi_cs - mid.phi_cs, std::max(mid.phi_cs_scatter, high.phi_cs_scatter));
}

TEST(ElementSlow, CriticalStateAngleGrowsWithRollingResistance) {
  const SpecimenResult& none = loose_critical_state(0.3, 0.0);
  const SpecimenResult& some = loose_critical_state(0.3, 0.1);
  const SpecimenResult& more = loose_critical_state(0.3, 0.3);
  EXPECT_GT(some.phi_cs - none.phi_cs, std::max(none.phi_cs_scatter, some.phi_cs_scatter));
  EXPECT_GT(more.phi_cs - some.phi_cs, std::max(some.phi_cs_scatter, more.phi_cs_scatter));
}

}  // namespace
}  // namespace trapdem
