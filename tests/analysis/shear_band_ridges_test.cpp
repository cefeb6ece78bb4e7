// The shear-band tracer on fields like a real DEM field (issue 12, section 2): bands with a branch
// leaving them near the top (the seed paper, section 6: "two additional bands then branch off from
// the primary shearing arms near the top ... and extend outwards") and spatially correlated
// fluctuation of the strain (a Gaussian random field with a correlation length of a few
// diameters), over several noise seeds. gamma_max is set directly on the triangles of a jittered
// packing of 2 mm particles, so the test is about the tracer, not the strain computation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <array>
#include <cstdlib>
#include <functional>
#include <random>

#include "analysis/field_smoothing.hpp"
#include "analysis/shear_bands.hpp"
#include "analysis_test_support.hpp"

using namespace trapdem;
using test::report;

namespace {

constexpr double d = 0.002;   // m, particle diameter
constexpr double B = 0.05;    // m, trapdoor width, centred at x = 0
constexpr double H = 0.2;     // m, specimen height
constexpr double fwhm_per_sigma = 2.3548200450309493;

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

// A Gaussian random field with covariance a^2 exp(-r^2 / (2 l^2)) by random Fourier features
// (Rahimi & Recht 2007): f(p) = a sqrt(2 / M) sum_m cos(k_m . p + phi_m), k_m ~ N(0, I / l^2),
// phi_m ~ U(0, 2 pi). Seeded, smooth, defined everywhere.
class GaussianRandomField {
 public:
  GaussianRandomField(double amplitude, double correlation_length, unsigned seed, int modes = 400)
      : scale_(amplitude * std::sqrt(2.0 / modes)) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> k(0.0, 1.0 / correlation_length);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
    for (int m = 0; m < modes; ++m) modes_.push_back({k(rng), k(rng), phase(rng)});
  }
  double operator()(Point2 p) const {
    double sum = 0.0;
    for (const auto& m : modes_) sum += std::cos(m.kx * p.x + m.kz * p.z + m.phase);
    return scale_ * sum;
  }

 private:
  struct Mode {
    double kx, kz, phase;
  };
  double scale_;
  std::vector<Mode> modes_;
};

// A straight ridge from `start` going up at `angle_deg` to the vertical, leaning outward (away
// from x = 0) when positive, on the side of start.x: a Gaussian of full width at half maximum
// `width` across it, with a round end below its start.
struct Ridge {
  Point2 start;
  double angle_deg;
  double peak;
  double width;
  double top = std::numeric_limits<double>::infinity();  // m, the ridge stops here (sharp)

  double direction_x() const { return (start.x < 0.0 ? -1.0 : 1.0) * std::sin(radians(angle_deg)); }
  double x_at(double z) const { return start.x + (z - start.z) * direction_x() / std::cos(radians(angle_deg)); }
  double operator()(Point2 p) const {
    if (p.z > top) return 0.0;
    const double ux = direction_x(), uz = std::cos(radians(angle_deg));
    const double dx = p.x - start.x, dz = p.z - start.z;
    const double t = std::max(0.0, dx * ux + dz * uz);  // along the ridge, clamped at its start
    const double nx = dx - t * ux, nz = dz - t * uz;
    const double sigma = width / fwhm_per_sigma;
    return peak * std::exp(-0.5 * (nx * nx + nz * nz) / (sigma * sigma));
  }
};

struct PlantedField {
  std::vector<Ridge> ridges;
  double noise_amplitude = 0.0;     // standard deviation of the random field
  double noise_correlation = 3.0 * d;
  unsigned seed = 1;
};

// gamma_max = | max over ridges + random field |: non-negative, like a maximum shear strain.
TriangleField planted_field(const test::Specimen& s, const PlantedField& planted) {
  const GaussianRandomField noise(planted.noise_amplitude, planted.noise_correlation, planted.seed);
  const auto centroids = triangle_centroids(s.mesh, s.nodes);
  std::vector<double> gamma(s.mesh.size());
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    double ridge = 0.0;
    for (const auto& r : planted.ridges) ridge = std::max(ridge, r(centroids[t]));
    gamma[t] = std::abs(ridge + (planted.noise_amplitude > 0.0 ? noise(centroids[t]) : 0.0));
  }
  return make_triangle_field(s.mesh, s.nodes, gamma);
}

const test::Specimen& specimen() {
  static const test::Specimen s = test::make_specimen(-0.15, 0.15, 0.0, H, 51);
  return s;
}

// The promise of docs/analysis.md: no trace point on or across the trapdoor centre line x = 0.
void expect_on_its_side(const ShearBand& band) {
  const bool left = band.side == BandSide::left;
  for (const auto& p : band.trace) EXPECT_TRUE(left ? p.x < 0.0 : p.x > 0.0) << "trace point at z = " << p.z;
  for (const auto& branch : band.branches) {
    for (const auto& p : branch.trace) EXPECT_TRUE(left ? p.x < 0.0 : p.x > 0.0) << "branch point at z = " << p.z;
  }
}

// A continuous ridge moves by at most the allowed step around its trend per slab (2 d): the
// largest lateral step between consecutive trace points per slab of height between them (a
// bridged slab doubles the height). Today's demo traces stepped up to 20 d in one slab.
double largest_jump(const ShearBand& band) {
  double jump = 0.0;
  const double slab = 2.0 * d;
  for (std::size_t k = 1; k < band.trace.size(); ++k) {
    const double dz = band.trace[k].z - band.trace[k - 1].z;
    jump = std::max(jump, std::abs(band.trace[k].x - band.trace[k - 1].x) * slab / dz);
  }
  return jump;
}

// Noise level of the tests: a random field of standard deviation 0.06 (a sixth of the 0.35
// ridge), correlated over 3 d. The limit of the method (measured when this test was written,
// docs/analysis.md): at 0.08 (a quarter of the ridge) every band stays on its ridge and the branch
// is found in 8 of 10; at 0.12 (a third) 4 of 10 bands are lost or leave their ridge.
constexpr double ridge_peak = 0.35;
const double noise_sd = std::getenv("TRAPDEM_TEST_NOISE_SD") ? std::atof(std::getenv("TRAPDEM_TEST_NOISE_SD")) : 0.06;


// Two primary bands leaning inward by 5 degrees (they approach each other going up, as the seed
// paper's bands that meet at the surface), 5 d wide; from each a branch leaves outward at 35
// degrees near the top (left at 0.12 m, right at 0.14 m), weaker (0.25).
// Tolerances: band angles within 2 degrees (the issue's); consecutive trace points within 5 d (one
// band width: a larger step leaves the band; today's demo traces stepped up to 20 d); the top of
// the trace within 2 d of the primary band (it did not take the branch). A branch counts as found
// when one is reported within 6 d of the planted height (two ridges 5 d wide smoothed at 2 d
// separate into two maxima only about 6 d above the point where they part; the branch's line is
// extrapolated back to the band) and within 5 degrees of its angle (a fit over 30-40 mm only).
struct BranchCase {
  double band_angle = -5.0, branch_angle = 35.0, left_branch_z = 0.12, right_branch_z = 0.14;
  Ridge left() const { return {{-0.5 * B, 0.0}, band_angle, ridge_peak, 5.0 * d}; }
  Ridge right() const { return {{0.5 * B, 0.0}, band_angle, ridge_peak, 5.0 * d}; }
  PlantedField field(double noise, unsigned seed) const {
    const Ridge l = left(), r = right();
    const Ridge lb{{l.x_at(left_branch_z), left_branch_z}, branch_angle, 0.25, 5.0 * d};
    const Ridge rb{{r.x_at(right_branch_z), right_branch_z}, branch_angle, 0.25, 5.0 * d};
    return {{l, r, lb, rb}, noise, 3.0 * d, seed};
  }
};

struct BandCheck {
  bool band_ok = false;      // angle, length, step and top on the primary band
  bool branch_found = false;
};

// Checks one band: the centre-line promise strictly (EXPECT); the rest returned for a tally.
BandCheck check_band_and_branch(const BranchCase& c, const ShearBand& band, unsigned seed) {
  const bool is_left = band.side == BandSide::left;
  const double planted_branch_z = is_left ? c.left_branch_z : c.right_branch_z;
  std::printf("[ measured ] seed %u %s: angle %.2f +- %.2f deg (planted %.0f), %zu points to %.0f mm (%s), "
              "largest step %.2f d, %zu branch(es)",
              seed, is_left ? "left" : "right", band.angle_deg, band.angle_error_deg, c.band_angle, band.trace.size(),
              band.height_reached * 1e3, band_end_name(band.end), largest_jump(band) / d, band.branches.size());
  BandCheck check;
  for (const auto& b : band.branches) {
    std::printf(" [at %.0f mm, %.1f +- %.1f deg, to %.0f mm]", b.height * 1e3, b.angle_deg, b.angle_error_deg,
                b.trace.back().z * 1e3);
    check.branch_found = check.branch_found || (std::abs(b.height - planted_branch_z) <= 6.0 * d &&
                                                std::abs(b.angle_deg - c.branch_angle) <= 5.0);
  }
  expect_on_its_side(band);
  check.band_ok = band.trace.size() > 40 && std::abs(band.angle_deg - c.band_angle) <= 2.0 &&
                  largest_jump(band) <= 5.0 * d &&
                  std::abs(band.trace.back().x - (is_left ? c.left() : c.right()).x_at(band.trace.back().z)) <= 2.0 * d;
  std::printf("%s%s\n", check.band_ok ? "" : "  <- band off its ridge", check.branch_found ? "" : "  <- branch not found");
  return check;
}

}  // namespace

TEST(ShearBandRidges, BandWithBranchWithoutNoise) {
  const BranchCase c;
  ShearBandSettings settings;
  settings.mean_diameter = d;
  const ShearBandPair pair = trace_shear_bands(planted_field(specimen(), c.field(0.0, 1)), {0.0, B, 0.0}, settings);
  for (const ShearBand* band : {&pair.left, &pair.right}) {
    const BandCheck check = check_band_and_branch(c, *band, 0);
    EXPECT_TRUE(check.band_ok) << "angle within 2 deg, steps within 5 d, on its primary band at the top";
    EXPECT_TRUE(check.branch_found) << "the branch is reported";
    EXPECT_EQ(band->branches.size(), 1u) << "and nothing else";
  }
}

// Five noise seeds, both bands each. No trace point crosses the centre line, and every band is
// within the tolerances above (the "angles within 2 deg"), in every case. The branch found
// in at least 8 of the 10: measured 9 (in the other a bump merges with the branch where it parts).
// Before the tracer kept the continuation in line with the band at a branch point, 9 of 10 bands
// held: in seed 1 a fluctuation interrupts the right band over two slabs where its branch parts,
// the trace turned onto the branch and the angle was 4.7 +- 12.9 deg instead of -5.
TEST(ShearBandRidges, BandWithBranchInCorrelatedNoise) {
  const BranchCase c;
  ShearBandSettings settings;
  settings.mean_diameter = d;
  int bands_ok = 0, branches = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const ShearBandPair pair =
        trace_shear_bands(planted_field(specimen(), c.field(noise_sd, seed)), {0.0, B, 0.0}, settings);
    for (const ShearBand* band : {&pair.left, &pair.right}) {
      const BandCheck check = check_band_and_branch(c, *band, seed);
      bands_ok += check.band_ok ? 1 : 0;
      branches += check.branch_found ? 1 : 0;
    }
  }
  report("bands on their ridge of 10", bands_ok, 10.0);
  report("branches found of 10", branches, 8.0);
  EXPECT_EQ(bands_ok, 10);
  EXPECT_GE(branches, 8);
}

// Planar bands at several angles in correlated noise, five seeds each: angles within 2 degrees,
// no crossing of the centre line, no jump.
TEST(ShearBandRidges, PlanarBandsInCorrelatedNoise) {
  ShearBandSettings settings;
  settings.mean_diameter = d;
  for (double angle : {-5.0, 0.0, 15.0, 30.0}) {
    double worst = 0.0;
    for (unsigned seed = 11; seed <= 15; ++seed) {
      const Ridge left{{-0.5 * B, 0.0}, angle, ridge_peak, 5.0 * d};
      const Ridge right{{0.5 * B, 0.0}, angle, ridge_peak, 5.0 * d};
      const PlantedField planted{{left, right}, noise_sd, 3.0 * d, seed};
      const ShearBandPair pair = trace_shear_bands(planted_field(specimen(), planted), {0.0, B, 0.0}, settings);
      for (const ShearBand* band : {&pair.left, &pair.right}) {
        EXPECT_NEAR(band->angle_deg, angle, 2.0) << "seed " << seed;
        EXPECT_GT(band->trace.size(), 40u) << "seed " << seed;
        expect_on_its_side(*band);
        EXPECT_LE(largest_jump(*band), 5.0 * d) << "seed " << seed;
        worst = std::max(worst, std::abs(band->angle_deg - angle));
      }
    }
    std::printf("[ measured ] planar bands at %g deg in correlated noise, 5 seeds: largest angle error %.2f deg "
                "(tolerance 2)\n", angle, worst);
  }
}

// Bands leaning inward by 25 degrees meet on the centre line at z = (B/2) / tan 25 = 53.6 mm and
// cross there (an X). Each trace stops at the centre line (end = centre_line), never crossing it;
// its height within one slab plus the smoothing length (4 d) of the meeting point, less the
// band's half width (5 d / 2 / sin 25 horizontally: the two ridges merge into one maximum
// on the line before their centres meet).
TEST(ShearBandRidges, BandsMeetingAtTheCentreLineStopThere) {
  ShearBandSettings settings;
  settings.mean_diameter = d;
  const Ridge left{{-0.5 * B, 0.0}, -25.0, ridge_peak, 5.0 * d};
  const Ridge right{{0.5 * B, 0.0}, -25.0, ridge_peak, 5.0 * d};
  const ShearBandPair pair =
      trace_shear_bands(planted_field(specimen(), {{left, right}, 0.0, 3.0 * d, 1}), {0.0, B, 0.0}, settings);
  const double meeting = 0.5 * B / std::tan(radians(25.0));
  for (const ShearBand* band : {&pair.left, &pair.right}) {
    expect_on_its_side(*band);
    EXPECT_EQ(band->end, BandEnd::centre_line);
    EXPECT_NEAR(band->angle_deg, -25.0, 2.0);
    report("meeting height below the crossing (d)", (meeting - band->height_reached) / d, 4.0 + 5.0);
    EXPECT_LE(band->height_reached, meeting + 4.0 * d);
    EXPECT_GE(band->height_reached, meeting - 9.0 * d);
  }
}

// The fit's standard error against a hand computation, on z = 0..5 (sum (z - mean)^2 = 17.5).
// Residuals alternating +-e about x = 0.1 z: lag-one correlation negative, no correction:
// SE(b) = sqrt(sum r^2 / (n - 2) / 17.5). Residuals of a parabola ((z - 2.5)^2 less its mean,
// orthogonal to a line, so the fit leaves them as they are): positively correlated,
// rho = sum r_k r_k+1 / sum r^2, n_eff = n (1 - rho) / (1 + rho) replaces n.
TEST(ShearBandRidges, FitStandardErrorByHand) {
  const auto fit_of = [](const std::function<double(double)>& x) {
    std::vector<BandTracePoint> trace;
    for (int k = 0; k < 6; ++k) trace.push_back({double(k), x(double(k)), 1.0, 0.0});
    return fit_trace_line(trace, 0.0, 0.0, 10.0);
  };
  const auto hand = [](const std::function<double(double)>& x) {
    double xm = 0.0, szx = 0.0;
    for (int k = 0; k < 6; ++k) xm += x(k) / 6.0;
    for (int k = 0; k < 6; ++k) szx += (k - 2.5) * (x(k) - xm);
    const double b = szx / 17.5, a = xm - b * 2.5;
    std::vector<double> r;
    for (int k = 0; k < 6; ++k) r.push_back(x(k) - a - b * k);
    double srr = 0.0, lag = 0.0;
    for (int k = 0; k < 6; ++k) srr += r[k] * r[k];
    for (int k = 0; k < 5; ++k) lag += r[k] * r[k + 1];
    const double rho = std::max(0.0, lag / srr), n_eff = 6.0 * (1.0 - rho) / (1.0 + rho);
    return std::array<double, 3>{b, std::sqrt(srr / (n_eff - 2.0) / 17.5), lag / srr};
  };
  const double e = 0.01;
  const std::function<double(double)> alternating = [&](double z) { return 0.1 * z + (int(z) % 2 ? e : -e); };
  const std::function<double(double)> parabola = [&](double z) { return 0.1 * z + e * ((z - 2.5) * (z - 2.5) - 35.0 / 12.0); };
  for (const auto* x : {&alternating, &parabola}) {
    const TraceLineFit fit = fit_of(*x);
    const auto [b, se, rho] = hand(*x);
    EXPECT_NEAR(fit.slope, b, 1e-14);
    EXPECT_NEAR(fit.residual_correlation, rho, 1e-12);
    EXPECT_NEAR(fit.slope_error, se, 1e-14);
    EXPECT_NEAR(band_angle_error_from_fit(fit), se / (1.0 + b * b) * 180.0 / std::numbers::pi, 1e-12);
  }
  EXPECT_LT(fit_of(alternating).residual_correlation, 0.0);
  EXPECT_GT(fit_of(parabola).residual_correlation, 0.1);
  EXPECT_NEAR(fit_of(parabola).slope, 0.1, 1e-14);  // the parabola is orthogonal to the line
}

// Smoothing: a constant field stays constant (normalised convolution, also at the edges); a
// Gaussian ridge of full width W widens to sqrt(W^2 + (2.355 L)^2) (Gaussians convolve) within
// 0.5 d (the triangles sample the field at about d); NaN stays NaN; L = 0 is the identity;
// a negative length is an input error.
TEST(ShearBandRidges, SmoothingKeepsConstantsAndWidensARidgeAsStated) {
  const auto& s = specimen();
  const auto centroids = triangle_centroids(s.mesh, s.nodes);
  TriangleField constant = make_triangle_field(s.mesh, s.nodes, std::vector<double>(s.mesh.size(), 0.3));
  constant.value[7] = std::numeric_limits<double>::quiet_NaN();
  const TriangleField smoothed = smooth_triangle_field(constant, 2.0 * d);
  double worst = 0.0;
  for (std::size_t t = 0; t < smoothed.size(); ++t) {
    if (t != 7) worst = std::max(worst, std::abs(smoothed.value[t] - 0.3));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_TRUE(std::isnan(smoothed.value[7]));
  EXPECT_EQ(smooth_triangle_field(constant, 0.0).value[3], constant.value[3]);
  EXPECT_THROW(smooth_triangle_field(constant, -d), std::runtime_error);

  const double W = 5.0 * d, L = 2.0 * d;
  const Ridge vertical{{0.0, -1.0}, 0.0, 1.0, W};
  std::vector<double> gamma(s.mesh.size());
  for (std::size_t t = 0; t < gamma.size(); ++t) gamma[t] = vertical(centroids[t]);
  const TriangleField ridge = smooth_triangle_field(make_triangle_field(s.mesh, s.nodes, gamma), L);
  const HorizontalProfile p = horizontal_profile(ridge, 0.09, 0.11, -0.03, 0.03, 0.25 * d, 0.25 * d);
  const std::size_t peak = index_of_maximum(p, -0.01, 0.01);
  const double expected = std::sqrt(W * W + (fwhm_per_sigma * L) * (fwhm_per_sigma * L) +
                                    (fwhm_per_sigma * 0.25 * d) * (fwhm_per_sigma * 0.25 * d));
  const double width = full_width_at_half_maximum(p, peak, 10.0 * d);
  report("smoothed ridge width error (d)", std::abs(width - expected) / d, 0.5);
  EXPECT_NEAR(width, expected, 0.5 * d);
}
