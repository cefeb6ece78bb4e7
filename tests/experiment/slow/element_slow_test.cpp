// The virtual element test's physics at large strain (slow: a specimen of 4000 frictionless spheres
// sheared slowly to 15 % (15-35 minutes here, by the load), and five of 1000 frictional spheres to
// 25 % axial strain; up to an hour with ctest -j2 on a loaded machine). In tests/experiment/slow: program test_experiment_slow, label slow,
// excluded from `make test` and run by `make test-slow`.
//
// 1. Frictionless spheres still have a macroscopic friction: Peyneau & Roux (2008), "Frictionless
//    bead packs have macroscopic friction, but no dilatancy", Phys. Rev. E 78, 011307, find an
//    internal friction angle of 5.76 deg (friction coefficient mu* = tau / sigma_n ~ 0.100) for
//    nearly rigid frictionless beads in simple shear in the quasi-static limit, in periodic cells
//    (no walls), no dilatancy, and mu* rising as a power of the inertial number I. What is
//    comparable: (a) simple shear and the biaxial test are both plane strain, and with coaxial
//    stress and strain rate and no dilatancy (psi = 0) the shear plane is a plane of zero
//    extension, on which tau / sigma_n = sin phi cos psi / (1 - sin phi sin psi) = sin phi (Davis
//    1968): so mu* is compared with the biaxial test's sin phi' = (sigma_1 - sigma_3) / (sigma_1 +
//    sigma_3) (tan 5.76 deg and sin 5.76 deg differ by 0.0005), not with a triaxial test's angle
//    (Lade-Duncan-like yield, Peyneau & Roux 2008b, PRE 78 041307); (b) their cells have no walls:
//    ours has six flat frictionless ones, along which the spheres order in layers, and the stress
//    ratio the walls measure is 0.017-0.039 above the contact stress of the interior three
//    diameters inside them (4000 spheres; docs/element.md). The interior's is the comparable one;
//    (c) their value is the limit I -> 0, ours at I = 2.3e-4 carries a rate excess, bounded from
//    our own rates. docs/element.md gives the runs behind the bands.
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

// The frictionless loose specimen sheared to 15 % at inertial number `inertial`, over the rows
// from 5 to 15 % (the frictionless specimens reach their steady state by 3-4 %): the mean sin phi
// from the walls and from the contacts of the interior `margin` mean diameters inside every wall
// (interior_contact_stress), and their difference, each with its standard error from the means of
// four blocks of consecutive rows (the rows are correlated over about 1 % of strain: their own
// standard deviation, ~0.025, would understate the error).
struct Estimate {
  double mean = 0.0, error = 0.0;
};
struct SteadyFriction {
  Estimate wall, interior, difference;  // difference: interior - wall, row by row
  double inertial = 0.0, final_volumetric_strain = 0.0, max_lateral_error = 0.0;
};

Estimate block_estimate(const std::vector<double>& x) {
  const std::size_t n = x.size(), block = n / 4;
  Estimate e;
  double blocks[4] = {};
  for (std::size_t k = 0; k < n; ++k) e.mean += x[k] / double(n);
  for (int b = 0; b < 4; ++b)
    for (std::size_t k = b * block; k < (b + 1) * block; ++k) blocks[b] += x[k] / double(block);
  const double block_mean = (blocks[0] + blocks[1] + blocks[2] + blocks[3]) / 4.0;
  double v = 0.0;
  for (double b : blocks) v += (b - block_mean) * (b - block_mean);
  e.error = std::sqrt(v / 3.0 / 4.0);
  return e;
}

SteadyFriction frictionless_steady_state(int particles, double inertial, double margin) {
  const std::string text = element_test_config("element-frictionless", 0.0, 0.0) +
                           fmt::format("particles = {}\nmax_axial_strain = 0.15\ncritical_state_window = 0.10\n"
                                       "inertial_number = {}\ninterior_margin = {}\n",
                                       particles, inertial, margin);
  Config c = Config::parse(text, "element-frictionless.toml");
  const ElementSetup setup = read_element_setup(c);
  ElementSpecimen sp = prepare_specimen(setup, Packing::loose, 50e3);
  const SpecimenResult r = shear_specimen(sp, setup);
  std::vector<double> wall, interior, difference;
  double inertial_sum = 0.0;
  for (const ElementRow& row : r.rows)
    if (row.axial_strain >= 0.05) {
      wall.push_back(row.sin_phi);
      interior.push_back(row.interior_sin_phi);
      difference.push_back(row.interior_sin_phi - row.sin_phi);
      inertial_sum += row.inertial_number;
    }
  SteadyFriction f;
  f.wall = block_estimate(wall);
  f.interior = block_estimate(interior);
  f.difference = block_estimate(difference);
  f.inertial = inertial_sum / double(wall.size());  // at the mean stress of the rows
  f.final_volumetric_strain = r.rows.back().volumetric_strain;
  f.max_lateral_error = r.max_lateral_error;
  std::fprintf(stderr,
               "frictionless, %d spheres, I %.3g: sin phi from the walls %.4f +- %.4f, interior (%.1f d) %.4f +- %.4f "
               "(%.2f deg), difference %.4f +- %.4f, final eps_v %.4f, lateral within %.4f\n",
               particles, f.inertial, f.wall.mean, f.wall.error, margin, f.interior.mean, f.interior.error,
               std::asin(f.interior.mean) * 180.0 / std::numbers::pi, f.difference.mean, f.difference.error,
               f.final_volumetric_strain, f.max_lateral_error);
  return f;
}

// The specimen and the bands, from the runs in docs/element.md ("Frictionless spheres"): 4000
// spheres, the interior 3 d inside every wall (~9 d across, a fifth of the box), I = 2.5e-4.
constexpr int kFrictionlessParticles = 4000;
constexpr double kFrictionlessInertial = 2.5e-4;
constexpr double kInteriorMargin = 3.0;  // mean diameters
// Run-to-run standard deviation of the interior's mean sin phi at this size and rate: two gas
// seeds gave 0.106 and 0.131 (block errors 0.003-0.004: a specimen's interior keeps its packing's
// own strength over the strain averaged, so the block error understates the scatter).
constexpr double kRunScatter = 0.018;
// What the finite rate adds at I = 2.3e-4: the interior's sin phi fell by 0.016 from I = 4.6e-4
// to 2.3e-4; the linear mu(I) (Jop et al. 2006) puts as much again above the limit. A slower
// approach (mu - mu0 ~ I^alpha, alpha < 1) would put more, and the quasi-static limit lower.
constexpr double kRateExcess = 0.016;
// The walls' layers: interior - wall was -0.017 to -0.039 (+-0.006) in every 4000-sphere run (two
// seeds, three rates); two standard errors beyond that range.
constexpr double kLayerEffectMin = 0.005, kLayerEffectMax = 0.06;

TEST(ElementSlow, FrictionlessSpheresInteriorFrictionMatchesThePublishedQuasiStaticValue) {
  const double published = 0.100;  // mu* = sin phi' in the quasi-static limit (5.76 deg), see the top
  const SteadyFriction f = frictionless_steady_state(kFrictionlessParticles, kFrictionlessInertial, kInteriorMargin);
  // No dilatancy: the volume stays within a few tenths of a per cent (docs/element.md: |eps_v| <= 0.6 %).
  EXPECT_LT(std::fabs(f.final_volumetric_strain), 0.01);
  EXPECT_LT(f.max_lateral_error, 0.01);
  // The comparable measure is the interior's: the published limit, plus what the rate adds,
  // within three run-to-run standard deviations. Wide ([0.046, 0.170]): one specimen of 4000
  // spheres is; the walls' own value (0.145-0.148) lies inside, so the next check is what tells
  // the two measures apart. It fails if the material's friction moves by ~0.05 or the interior
  // measure breaks.
  EXPECT_GT(f.interior.mean, published - 3.0 * kRunScatter)
      << "interior sin phi " << f.interior.mean << " +- " << f.interior.error;
  EXPECT_LT(f.interior.mean, published + kRateExcess + 3.0 * kRunScatter)
      << "interior sin phi " << f.interior.mean << " +- " << f.interior.error;
  // The known discrepancy, stated: the stress ratio the walls measure includes the ordered layers
  // along the six flat walls, which add 0.017-0.039 to sin phi (1-2 deg) at this size.
  EXPECT_LT(f.difference.mean, -kLayerEffectMin) << "interior - wall sin phi";
  EXPECT_GT(f.difference.mean, -kLayerEffectMax) << "interior - wall sin phi";
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
