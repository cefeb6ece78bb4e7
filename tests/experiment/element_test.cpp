// The virtual element test (issue 17), fast checks on a specimen of a few hundred spheres: the
// servo holds the confining stress, the contact (Love-Weber) stress equals the wall stress at
// rest, the angles are read correctly off the curves, and bad inputs are refused clearly. The
// frictionless critical state and the trend with mu and mu_r take thousands of particles to large
// strain: tests/experiment/slow/element_slow_test.cpp.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <omp.h>

#include "core/errors.hpp"
#include "dem/wall.hpp"
#include "element_test_config.hpp"
#include "experiment/element_config.hpp"
#include "experiment/element_output.hpp"
#include "experiment/element_servo.hpp"
#include "experiment/element_stress.hpp"
#include "experiment/element_test.hpp"
#include "io/config.hpp"

namespace trapdem {
namespace {

// The shared test configuration (element_test_config.hpp) with mu = 0.3 and a few hundred
// particles; the next key appended goes on line 19.
const std::string kBase = element_test_config("element-fast", 0.3, 0.0) + "particles = 300\n";

ElementSetup setup_from(const std::string& text, const std::vector<std::string>& overrides = {}) {
  Config c = Config::parse(text, "element.toml");
  c.apply_overrides(overrides);
  return read_element_setup(c);
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    setup_from(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ElementConfig, ReadsTheElementKeysAndTheRunConfigurationsMaterial) {
  const ElementSetup s = setup_from(std::string(kBase) + "test = \"triaxial\"\nconfining = [25e3, 100e3]\n");
  EXPECT_EQ(s.settings.kind, ElementTestKind::triaxial);
  ASSERT_EQ(s.settings.confining.size(), 2u);
  EXPECT_DOUBLE_EQ(s.settings.confining[1], 100e3);
  EXPECT_EQ(s.settings.particles, 300);
  EXPECT_DOUBLE_EQ(s.material.particle.kinetic_friction, 0.3);
  EXPECT_DOUBLE_EQ(s.material.sizes.mean_diameter(), 0.002);
  // The time step is the run configuration's: 0.2 sqrt(m_min / k_n).
  const double m_min = 2500.0 * std::numbers::pi / 6.0 * std::pow(0.0019, 3);
  EXPECT_NEAR(s.time_step, 0.2 * std::sqrt(m_min / 1e6), 1e-12);
  // I = eps_dot d / sqrt(p / rho_s) = 1e-3 at 50 kPa: eps_dot = 1e-3 sqrt(20) / 0.002 = 2.236 1/s.
  EXPECT_NEAR(shear_strain_rate(s, 50e3), 1e-3 * std::sqrt(50e3 / 2500.0) / 0.002, 1e-12);
}

TEST(ElementConfig, RefusesANonPositiveConfiningStressNamingTheKeyAndLine) {
  const std::string in_file = error_of(std::string(kBase) + "confining = [50e3, -10.0]\n");
  EXPECT_NE(in_file.find("element.toml:19:"), std::string::npos) << in_file;
  EXPECT_NE(in_file.find("element.confining"), std::string::npos) << in_file;
  EXPECT_NE(in_file.find("in (0, 1000000000] (Pa)"), std::string::npos) << in_file;
  const std::string zero = error_of(kBase, {"element.confining=[0.0]"});
  EXPECT_NE(zero.find("element.confining"), std::string::npos) << zero;
  EXPECT_NE(zero.find("in (0, "), std::string::npos) << zero;
  // The library refuses it too when called directly.
  const ElementSetup s = setup_from(kBase);
  EXPECT_THROW(prepare_specimen(s, Packing::dense, 0.0), InputError);
}

TEST(ElementConfig, RefusesAConfigurationWithoutParticles) {
  const std::string message = error_of("name = \"no-particles\"\n[contact]\nstatic_friction = 0.3\n[pluviation]\ncount = 10\n");
  EXPECT_NE(message.find("element.toml"), std::string::npos) << message;
  EXPECT_NE(message.find("no [particles] table"), std::string::npos) << message;
}

TEST(ElementConfig, RefusesUnknownElementKeysAndBadChoices) {
  const std::string unknown = error_of(std::string(kBase) + "confinement = 5e4\n");
  EXPECT_NE(unknown.find("element.confinement"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("element.toml:19"), std::string::npos) << unknown;
  const std::string test = error_of(kBase, {"element.test=shear"});
  EXPECT_NE(test.find("element.test"), std::string::npos) << test;
  EXPECT_NE(test.find("triaxial"), std::string::npos) << test;
}

// Synthetic curves with known angles: a peak of sin phi = 0.5 (30 deg) at 5 % where the specimen
// dilates at d eps_v / d eps_1 = -0.5 (sin psi = 0.5 / 2.5 = 0.2), then a plateau at sin phi = 0.4.
TEST(ElementSummary, ReadsThePeakTheCriticalStateAndTheDilatancyOffTheRows) {
  SpecimenResult r;
  for (int k = 1; k <= 120; ++k) {
    ElementRow row;
    row.axial_strain = 0.0025 * k;
    const double e = row.axial_strain;
    row.sin_phi = e <= 0.05 ? 0.5 * e / 0.05 : (e < 0.10 ? 0.5 - 0.1 * (e - 0.05) / 0.05 : 0.4);
    row.volumetric_strain = -0.5 * e;
    row.lateral_error = k == 7 ? 0.004 : 0.001;
    r.rows.push_back(row);
  }
  summarise_specimen(r, 0.05);
  EXPECT_NEAR(r.phi_peak, 30.0, 1e-9);
  EXPECT_NEAR(r.axial_strain_at_peak, 0.05, 1e-12);
  EXPECT_NEAR(r.phi_cs, std::asin(0.4) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(r.phi_cs_scatter, 0.0, 1e-9);
  EXPECT_NEAR(r.psi_peak, std::asin(0.2) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(r.max_lateral_error, 0.004);
}

// One prepared specimen for the stress and servo checks (preparing takes most of the time).
class ElementSpecimenTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // A few hundred spheres: one thread is faster than two (and ctest runs programs side by side).
    threads_ = omp_get_max_threads();
    omp_set_num_threads(1);
    setup_ = new ElementSetup(setup_from(kBase));
    specimen_ = new ElementSpecimen(prepare_specimen(*setup_, Packing::dense, 50e3));
  }
  static void TearDownTestSuite() {
    delete specimen_;
    delete setup_;
    omp_set_num_threads(threads_);
  }
  static int threads_;
  static ElementSetup* setup_;
  static ElementSpecimen* specimen_;
};
int ElementSpecimenTest::threads_ = 1;
ElementSetup* ElementSpecimenTest::setup_ = nullptr;
ElementSpecimen* ElementSpecimenTest::specimen_ = nullptr;

// In static equilibrium the contact stress and the wall stress are the same sum (element_stress.hpp);
// what separates them is the particles' inertia, small at rest: 2 % is the tolerance.
TEST_F(ElementSpecimenTest, LoveWeberStressEqualsTheWallStressInTheIsotropicState) {
  const IsotropicState& iso = specimen_->isotropic;
  EXPECT_NEAR(iso.love_weber_mean() / iso.wall_mean(), 1.0, 0.02);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(iso.love_weber_stress[a] / iso.wall_stress[a], 1.0, 0.02) << "axis " << a;
  // The instantaneous tensor too, and it has no shear part worth the name.
  const Stress3 s = love_weber_stress(*specimen_->sim, specimen_->box);
  const double p = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  EXPECT_NEAR(p / 50e3, 1.0, 0.02);
  EXPECT_LT(std::fabs(s[0][1]) / p, 0.05);
  // A dense frictionless compression of +-5 % spheres ends near random close packing (~0.64)
  // inside; the looser layer along the walls lowers the box average by ~0.07 in a specimen only
  // 6-7 diameters wide (0.56 measured).
  EXPECT_GT(iso.solid_fraction, 0.54);
  EXPECT_LT(iso.solid_fraction, 0.66);
}

// The interior's contact stress recomputes each pair's force from its overlap, velocities and
// tangential spring (element_stress.hpp). With no margin every pair's contact point is inside, so
// it must equal the whole box's Love-Weber sum, whose pair part comes from the engine's own forces,
// less the wall contacts' part: the same tensor, shear components included, to the omitted
// tangential dashpot (the specimen is at rest: 0.4 Pa of 50 kPa measured, 5 Pa asked). A sign slip in the tangential spring
// (the specimen has mu = 0.3 and carries tangential forces) or in the branch vector breaks it.
TEST_F(ElementSpecimenTest, InteriorContactStressIsThePairPartOfTheLoveWeberSumWithoutAMargin) {
  const Simulation& sim = *specimen_->sim;
  const ElementBox& box = specimen_->box;
  const Stress3 whole = love_weber_stress(sim, box);
  const Stress3 pairs = interior_contact_stress(sim, box, 0.0);
  // The wall contacts' part: f_iw (x) (x_i - c_iw) over the box volume (element_stress.hpp).
  Stress3 walls{};
  const WallList& wl = sim.wall_candidates();
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::uint32_t k = wl.first[i]; k < wl.first[i + 1]; ++k) {
      const Vec3 arm = p.position[i] - wall_proximity(sim.walls()[wl.wall[k]], p.position[i]).point;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) walls[a][b] += wl.force[k][a] * arm[b] / box.volume(sim);
    }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      EXPECT_NEAR(pairs[a][b] + walls[a][b], whole[a][b], 1e-4 * 50e3) << "component " << a << b;
    }
  // The pairs carry most of the stress (the walls' part is the layer along them).
  EXPECT_GT(pairs[0][0], 0.5 * whole[0][0]);
  // An interior one diameter inside every wall is still at the confining stress, within the
  // surface error of order d / L_in (element_stress.hpp: an interior 4-5 diameters wide, ~0.2-0.25),
  // and isotropic, within the fluctuation of so small a sample (~100 spheres' contacts). The level
  // moves with round-off alone: 0.86-0.89 of 50 kPa on the three axes, and 0.82-0.87 after a change
  // that moved only the moments of the list rebuilds (2026-12-05).
  const Stress3 inner = interior_contact_stress(sim, box, setup_->material.sizes.mean_diameter());
  const double inner_mean = (inner[0][0] + inner[1][1] + inner[2][2]) / 3.0;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(inner[a][a] / 50e3, 1.0, 0.25) << "axis " << a;
    EXPECT_NEAR(inner[a][a] / inner_mean, 1.0, 0.08) << "axis " << a;
  }
  // No interior left: refused with a message naming the axis.
  EXPECT_THROW(interior_contact_stress(sim, box, box.length(sim, 0)), SimulationError);
}

TEST_F(ElementSpecimenTest, ServoHoldsTheLateralStressAfterTheIsotropicStageAndDuringShear) {
  EXPECT_LT(specimen_->isotropic.max_axis_error, 0.01);
  ElementSetup shear = *setup_;
  shear.settings.max_axial_strain = 0.04;
  shear.settings.row_strain = 0.005;
  shear.settings.critical_state_window = 0.02;
  const SpecimenResult r = shear_specimen(*specimen_, shear);
  ASSERT_GE(r.rows.size(), 8u);
  for (const ElementRow& row : r.rows) {
    EXPECT_LT(row.lateral_error, 0.01) << "at axial strain " << row.axial_strain;
    EXPECT_GT(row.deviator, 0.0);
  }
  // Plane strain: the y walls did not move.
  EXPECT_NEAR(r.rows.back().axial_strain, 0.04, 0.003);
  EXPECT_GT(r.phi_peak, 5.0);
}

// The tiny preset's law, restitution 0.5: the contact's dashpot, c_n ~ 2.5 k_n dt at its time step,
// answers a wall's speed within the step. A servo gain from the springs alone (k_n dt) then
// overshot at every step: a 500-sphere dense specimen's stresses sat 3-5 % above the target for
// 120 000 steps (it never settled), this 150-sphere one's measuring window ended 18 % off on
// average and 59 % on one axis. With the dashpot in the gain it settles like the others, within
// the 0.5 % the isotropic stage demands of each axis.
TEST(ElementSpecimen, ASpecimenOfTheTinyPresetsLowRestitutionLawSettles) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  Config c = Config::load_file(TRAPDEM_SOURCE_DIR "/presets/tiny.toml");
  c.apply_overrides({"element.particles=150"});
  const ElementSetup setup = read_element_setup(c);
  ASSERT_DOUBLE_EQ(setup.material.particle.restitution, 0.5);
  const ElementSpecimen sp = prepare_specimen(setup, Packing::dense, 50e3);
  omp_set_num_threads(threads);
  EXPECT_LT(sp.isotropic.max_axis_error, 0.005);
  EXPECT_NEAR(sp.isotropic.wall_mean() / 50e3, 1.0, 0.005);
}

}  // namespace
}  // namespace trapdem

namespace trapdem {
namespace {

// A dense specimen of 200 dimers (aspect 1.5, particles.shape) at 50 kPa: the same equilibrium
// check as for spheres, with the clumps' contacts referred to their centres of mass
// (element_stress.hpp). Referred to the member spheres' centres instead, the sum adds each body's
// moment sum f (x) (x_member - X), which does not vanish for a body of several members: the check
// then misses by ~10 % (measured: the mutation below). 2 %, as for spheres. The solid fraction is
// the unions' volume over the box's; a dimer specimen packs denser than spheres (random close
// packing of dimers of aspect 1.5 is ~0.70 against 0.64), less the looser layer along the walls.
TEST(ElementClumps, LoveWeberStressOfDimersEqualsTheWallStress) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ElementSetup setup = setup_from(element_test_config("element-dimers", 0.3, 0.0) + "particles = 200\n",
                                        {"particles.shape.kind=\"dimer\"", "particles.shape.aspect=1.5"});
  ASSERT_TRUE(setup.material.shape.is_clump());
  const ElementSpecimen sp = prepare_specimen(setup, Packing::dense, 50e3);
  omp_set_num_threads(threads);
  const IsotropicState& iso = sp.isotropic;
  EXPECT_EQ(sp.sim->bodies().size(), 200u);
  EXPECT_EQ(sp.sim->particles().size(), 400u);
  EXPECT_NEAR(iso.wall_mean() / 50e3, 1.0, 0.02);
  EXPECT_NEAR(iso.love_weber_mean() / iso.wall_mean(), 1.0, 0.02);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(iso.love_weber_stress[a] / iso.wall_stress[a], 1.0, 0.02) << "axis " << a;
  EXPECT_GT(iso.solid_fraction, 0.54);
  EXPECT_LT(iso.solid_fraction, 0.72);
  EXPECT_GT(iso.coordination, 3.0) << "contacts per dimer";
  if (std::getenv("TRAPDEM_TEST_REPORT"))
    std::printf("    [report] dimers: solid fraction %.4f, z %.2f, wall p %.1f Pa, Love-Weber p %.1f Pa (%.4f), %lld steps\n",
                iso.solid_fraction, iso.coordination, iso.wall_mean(), iso.love_weber_mean(),
                iso.love_weber_mean() / iso.wall_mean(), static_cast<long long>(iso.steps));
}

}  // namespace
}  // namespace trapdem

namespace trapdem {
namespace {

TEST(ElementConfig, ReadsThePackingsAndRefusesAnUnknownOrRepeatedOne) {
  const ElementSetup s = setup_from(kBase, {"element.packings=[\"loose\", \"mu_prep=0.05\", \"mu_prep=0.1\"]"});
  ASSERT_EQ(s.settings.packings.size(), 3u);
  EXPECT_EQ(s.settings.packings[0], Packing::loose);
  EXPECT_EQ(s.settings.packings[2], Packing::prepared_with_friction(0.1));
  const std::vector<Packing> by_default = setup_from(kBase).settings.packings;
  ASSERT_EQ(by_default.size(), 2u);
  EXPECT_EQ(by_default[0], Packing::dense);
  EXPECT_EQ(by_default[1], Packing::loose);
  for (const char* bad : {"mu_prep=-0.1", "medium", "mu_prep=", "mu_prep=0.1x"}) {
    const std::string message = error_of(std::string(kBase) + "packings = [\"dense\", \"" + bad + "\"]\n");
    EXPECT_NE(message.find("element.toml:19"), std::string::npos) << message;
    EXPECT_NE(message.find("element.packings"), std::string::npos) << message;
    EXPECT_NE(message.find("\"mu_prep=X\""), std::string::npos) << message;
    EXPECT_NE(message.find(bad), std::string::npos) << message;
  }
  const std::string twice = error_of(kBase, {"element.packings=[\"mu_prep=0.1\", \"mu_prep=0.10\"]"});
  EXPECT_NE(twice.find("named twice"), std::string::npos) << twice;
  const std::string none = error_of(kBase, {"element.packings=[]"});
  EXPECT_NE(none.find("at least one packing"), std::string::npos) << none;
}

TEST(ElementPacking, NamesAndComparesThePreparations) {
  EXPECT_EQ(to_string(Packing::dense), "dense");
  EXPECT_EQ(to_string(Packing::loose), "loose");
  EXPECT_EQ(to_string(Packing::prepared_with_friction(0.1)), "mu_prep=0.1");
  EXPECT_EQ(Packing::prepared_with_friction(0.1), Packing::prepared_with_friction(0.1));
  EXPECT_FALSE(Packing::prepared_with_friction(0.1) == Packing::prepared_with_friction(0.2));
  EXPECT_FALSE(Packing::prepared_with_friction(0.0) == Packing::dense) << "the same law, another preparation";
  ASSERT_TRUE(packing_from_name("mu_prep=0.25").has_value());
  EXPECT_EQ(*packing_from_name("mu_prep=0.25"), Packing::prepared_with_friction(0.25));
  EXPECT_EQ(*packing_from_name(to_string(Packing::prepared_with_friction(0.125))), Packing::prepared_with_friction(0.125));
}

// The preparation friction sets the density between the dense (frictionless compression) and
// the loose (the particles' own mu = 0.3) specimen of the same gas: 300 spheres at 50 kPa, one
// compressed with mu_prep = 0.08. Measured (TRAPDEM_TEST_REPORT) over gas seeds 1, 2, 3: dense
// 0.5630 / 0.5579 / 0.5585, mu_prep 0.08 0.5459 / 0.5514 / 0.5429, loose 0.5363 / 0.5369 / 0.5227;
// the pairs (same gas) are >= 0.0065 apart, the seeds move each by up to 0.005 (this small
// specimen's looser layers along the walls keep all three below the bulk's 0.64 / 0.58). The check
// is the order, at seed 1, and that the in-between specimen ends at the confining stress under its
// real law (the switch of law does not leave it off its target).
TEST(ElementPacking, APreparationFrictionGivesADensityBetweenDenseAndLoose) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ElementSetup setup = setup_from(kBase);
  double fraction[3];
  const Packing packings[3] = {Packing::dense, Packing::prepared_with_friction(0.08), Packing::loose};
  for (int k = 0; k < 3; ++k) {
    const ElementSpecimen sp = prepare_specimen(setup, packings[k], 50e3);
    fraction[k] = sp.isotropic.solid_fraction;
    EXPECT_LT(sp.isotropic.max_axis_error, 0.005) << to_string(packings[k]);
    EXPECT_EQ(sp.sim->particle_law().kinetic_friction, 0.3) << to_string(packings[k]) << ": sheared with its real law";
    if (std::getenv("TRAPDEM_TEST_REPORT"))
      std::printf("    [report] %s: solid fraction %.4f, z %.2f, %lld steps\n", to_string(packings[k]).c_str(),
                  fraction[k], sp.isotropic.coordination, static_cast<long long>(sp.isotropic.steps));
  }
  omp_set_num_threads(threads);
  EXPECT_GT(fraction[0], fraction[1]);
  EXPECT_GT(fraction[1], fraction[2]);
}

// element.json's angles come from the dense and the loose specimen; an in-between one adds a
// specimen but not an angle row.
TEST(ElementPacking, TheAnglesComeFromTheDenseAndLooseSpecimensOnly) {
  ElementResult result;
  result.settings.confining = {50e3};
  auto specimen = [](Packing packing, double peak, double cs) {
    SpecimenResult s;
    s.packing = packing;
    s.confining = 50e3;
    s.phi_peak = peak;
    s.phi_cs = cs;
    s.rows.push_back(ElementRow{});
    return s;
  };
  result.specimens = {specimen(Packing::dense, 40.0, 30.0), specimen(Packing::loose, 31.0, 29.0),
                      specimen(Packing::prepared_with_friction(0.1), 35.0, 50.0)};
  const std::vector<ElementAngles> angles = element_angles(result);
  ASSERT_EQ(angles.size(), 1u);
  EXPECT_DOUBLE_EQ(angles[0].phi_peak, 40.0);
  EXPECT_DOUBLE_EQ(angles[0].phi_cs, 29.5);
  EXPECT_NE(element_csv(result).find("mu_prep=0.1"), std::string::npos);
}

}  // namespace
}  // namespace trapdem
