// The study file: scales and cases in the order written, recipes composed as documented, and every
// mistake reported with the file, line and key.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "core/text_escape.hpp"
#include "experiment/experiment_config.hpp"
#include "io/config.hpp"
#include "run_command.hpp"
#include "study/study_definition.hpp"
#include "study_file.hpp"
#include "study/study_runner.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

using study_test::error_of;
using study_test::write_study;

const char* kStudy = R"(name = "order"
description = "cases out of alphabetical order"
default_scale = "small"
[scales.small]
preset = "tiny"
[scales.small.set]
trapdoor.travel = 0.002
[scales.big]
preset = "demo"
[report]
contours_at = 0.002
[cases.zeta]
label = "Zeta"
[cases.zeta.set.contact]
kinetic_friction = 0.3
rolling_model = "constant_torque"
[cases.alpha]
preset = "demo"
[cases.alpha.set]
output.snapshot_displacements = [0.0, 0.001]
)";

}  // namespace

TEST(StudyDefinition, ScalesAndCasesInFileOrder) {
  const StudyDefinition s = load_study(write_study("order.toml", kStudy));
  ASSERT_EQ(s.scales.size(), 2u);
  EXPECT_EQ(s.scales[0].name, "small");
  EXPECT_EQ(s.scales[1].name, "big");
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[0].name, "zeta");  // not sorted by name
  EXPECT_EQ(s.cases[0].label, "Zeta");
  EXPECT_EQ(s.cases[1].name, "alpha");
  EXPECT_EQ(s.cases[1].label, "alpha");  // default: the name
  EXPECT_EQ(s.default_scale, "small");
  EXPECT_DOUBLE_EQ(s.report.contours_at, 0.002);
  EXPECT_DOUBLE_EQ(s.report.angle_of_draw_deg, 30.0);
}

TEST(StudyDefinition, RecipeIsScaleBaseThenScaleThenCaseOverrides) {
  const StudyDefinition s = load_study(write_study("order.toml", kStudy));
  const ConfigRecipe zeta = case_recipe(s.cases[0], s.scale("small"));
  EXPECT_EQ(zeta.preset, "tiny");
  EXPECT_EQ(zeta.overrides, (std::vector<std::string>{"trapdoor.travel=0.002", "contact.kinetic_friction=0.3",
                                                      "contact.rolling_model=\"constant_torque\"", "name=\"zeta\""}));
  // A case's own base replaces the scale's; the scale's overrides still apply.
  const ConfigRecipe alpha = case_recipe(s.cases[1], s.scale("small"));
  EXPECT_EQ(alpha.preset, "demo");
  EXPECT_EQ(alpha.overrides, (std::vector<std::string>{"trapdoor.travel=0.002", "output.snapshot_displacements=[0.0, 0.001]",
                                                       "name=\"alpha\""}));
  // The overrides are valid --set text: applied to a document they give the values written.
  Config c = Config::parse("", "test");
  c.apply_overrides(zeta.overrides);
  EXPECT_DOUBLE_EQ(c.get_double("contact.kinetic_friction", 0.0), 0.3);
  EXPECT_EQ(c.get_string("contact.rolling_model", ""), "constant_torque");
  EXPECT_EQ(c.get_string("name", ""), "zeta");
}

TEST(StudyDefinition, UnknownScaleListsTheKnownOnes) {
  const StudyDefinition s = load_study(write_study("order.toml", kStudy));
  try {
    s.scale("paper");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no scale named 'paper'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("small, big"), std::string::npos) << e.what();
  }
}

TEST(StudyDefinition, MistakesNameFileLineAndKey) {
  const std::string base = "[scales.s]\npreset = \"tiny\"\n";
  // Unknown key, with its line.
  std::string e = error_of(base + "[cases.a]\nlabl = \"A\"\n");
  EXPECT_NE(e.find("bad.toml:4"), std::string::npos) << e;
  EXPECT_NE(e.find("cases.a.labl"), std::string::npos) << e;
  // A case name that cannot be a folder.
  e = error_of(base + "[cases.\"a/b\"]\nlabel = \"A\"\n");
  EXPECT_NE(e.find("folder name"), std::string::npos) << e;
  // Both a preset and a config.
  e = error_of(base + "[cases.a]\npreset = \"tiny\"\nconfig = \"x.toml\"\n");
  EXPECT_NE(e.find("either preset or config"), std::string::npos) << e;
  // A config file that is not there, named with the study's folder.
  e = error_of(base + "[cases.a]\nconfig = \"nowhere.toml\"\n");
  EXPECT_NE(e.find("nowhere.toml not found"), std::string::npos) << e;
  // No cases; no scales; a scale without a base; a default scale that does not exist.
  EXPECT_NE(error_of(base).find("cases"), std::string::npos);
  EXPECT_NE(error_of("[cases.a]\n").find("scales"), std::string::npos);
  e = error_of("[scales.s]\ndescription = \"x\"\n[cases.a]\n");
  EXPECT_NE(e.find("a preset or a config"), std::string::npos) << e;
  e = error_of("default_scale = \"paper\"\n" + base + "[cases.a]\n");
  EXPECT_NE(e.find("no scale named 'paper'"), std::string::npos) << e;
  // A table where a value belongs and a value where a table belongs.
  e = error_of(base + "[cases.a]\nset = 3\n");
  EXPECT_NE(e.find("cases.a.set"), std::string::npos) << e;
  e = error_of(base + "[report]\ncontours_at = -1\n[cases.a]\n");
  EXPECT_NE(e.find("report.contours_at"), std::string::npos) << e;
}

TEST(StudyDefinition, ThePaperStudyIsTable2) {
  const StudyDefinition s = load_study(fs::path(TRAPDEM_SOURCE_DIR) / "studies" / "paper-table2.toml");
  ASSERT_EQ(s.cases.size(), 4u);
  // Table 2: (mu_k, mu_r) per case; mu_s = 0.18 in all.
  const std::vector<std::pair<double, double>> table2 = {{0.18, 0.001}, {0.2, 0.2}, {0.5, 0.2}, {0.5, 0.4}};
  for (std::size_t k = 0; k < 4; ++k) {
    Config c = Config::parse("", "test");
    c.apply_overrides(case_recipe(s.cases[k], s.scale("paper")).overrides);
    EXPECT_DOUBLE_EQ(c.get_double("contact.static_friction", 0.0), 0.18) << s.cases[k].name;
    EXPECT_DOUBLE_EQ(c.get_double("contact.kinetic_friction", 0.0), table2[k].first) << s.cases[k].name;
    EXPECT_DOUBLE_EQ(c.get_double("contact.rolling_friction", 0.0), table2[k].second) << s.cases[k].name;
  }
  EXPECT_EQ(s.scale("paper").base.preset, "paper-calibrated");
  EXPECT_EQ(s.scale("demo").base.preset, "demo");
  EXPECT_DOUBLE_EQ(s.report.contours_at, 0.01);
}

// Every case of the paper study resolves and validates at every scale (what the study checks before
// its first run), and at the paper scale each case is its paper preset: the same contact law.
TEST(StudyDefinition, ThePaperStudyResolvesAtEveryScale) {
  const StudyDefinition s = load_study(fs::path(TRAPDEM_SOURCE_DIR) / "studies" / "paper-table2.toml");
  const std::vector<std::string> presets = {"paper-calibrated", "paper-rf1", "paper-rf2", "paper-rf3"};
  for (std::size_t k = 0; k < s.cases.size(); ++k) {
    for (const StudyScale& scale : s.scales) {
      Config resolved = Config::parse(resolved_case_configuration(s.cases[k], scale, app::preset_directory()), s.cases[k].name);
      EXPECT_EQ(resolved.get_string("name", ""), s.cases[k].name);
      // Its own description, not the base's (which names Calibrated in every case at the paper scales).
      EXPECT_EQ(resolved.get_string("description", "").find("Table 2 case " + s.cases[k].label + ":"), 0u)
          << s.cases[k].name << " at " << scale.name;
    }
    Config study_case = Config::parse(resolved_case_configuration(s.cases[k], s.scale("paper"), app::preset_directory()), "study");
    Config preset = Config::load_file((app::preset_directory() / (presets[k] + ".toml")).string());
    for (const char* key : {"contact.static_friction", "contact.kinetic_friction", "contact.rolling_friction",
                            "contact.rolling_model", "contact.restitution", "box.width", "trapdoor.width"})
      EXPECT_EQ(study_case.require_value_text(key), preset.require_value_text(key)) << presets[k] << " " << key;
    // The paper scale adds the shortcuts docs/validation.md validated; paper-preset is the preset as it is.
    EXPECT_DOUBLE_EQ(study_case.get_double("contact.normal_stiffness", 0.0), 5.0e4);
    EXPECT_DOUBLE_EQ(study_case.get_double("contact.tangential_stiffness", 0.0), 2.5e4);
    EXPECT_DOUBLE_EQ(study_case.get_double("numerics.time_step_fraction", 0.0), 0.3);
    EXPECT_DOUBLE_EQ(study_case.get_double("pluviation.flow_rate", -1.0), 0.0);
    EXPECT_DOUBLE_EQ(study_case.get_double("trapdoor.rate", 0.0), 0.1);
    Config as_preset =
        Config::parse(resolved_case_configuration(s.cases[k], s.scale("paper-preset"), app::preset_directory()), "study");
    for (const char* key : {"contact.normal_stiffness", "numerics.time_step_fraction", "pluviation.flow_rate",
                            "trapdoor.rate"})
      EXPECT_EQ(as_preset.require_value_text(key), preset.require_value_text(key)) << presets[k] << " " << key;
    // paper-fast is `paper` with two more of them (a longer step, a faster rain) and nothing else changed.
    Config fast =
        Config::parse(resolved_case_configuration(s.cases[k], s.scale("paper-fast"), app::preset_directory()), "study");
    EXPECT_DOUBLE_EQ(fast.get_double("numerics.time_step_fraction", 0.0), 0.4);
    EXPECT_DOUBLE_EQ(fast.get_double("pluviation.drop_height", 0.0), 0.08);
    for (const char* key : {"contact.normal_stiffness", "contact.tangential_stiffness", "contact.static_friction",
                            "contact.kinetic_friction", "contact.rolling_friction", "pluviation.flow_rate",
                            "pluviation.count", "trapdoor.rate", "trapdoor.travel", "spin_up.g_level"})
      EXPECT_EQ(fast.require_value_text(key), study_case.require_value_text(key)) << presets[k] << " " << key;
  }
}

// The seed-law study (issue 36) is paper-table2's cases with Blaze-DEM's law: at every scale each
// case resolves with the Blaze models and Table 2's mu_k, mu_r, and at paper-fast it is
// paper-table2's paper-fast case but for the contact law's models.
TEST(StudyDefinition, TheSeedLawStudyIsThePaperStudyWithBlazeDemsLaw) {
  const fs::path studies = fs::path(TRAPDEM_SOURCE_DIR) / "studies";
  const StudyDefinition seed = load_study(studies / "seed-law.toml");
  const StudyDefinition ours = load_study(studies / "paper-table2.toml");
  ASSERT_EQ(seed.cases.size(), ours.cases.size());
  for (std::size_t k = 0; k < seed.cases.size(); ++k) {
    for (const StudyScale& scale : seed.scales) {
      const std::vector<std::string>& set = scale.base.overrides;
      if (std::any_of(set.begin(), set.end(), [](const std::string& o) { return o.starts_with("packing.from="); })) {
        // A scale that starts from another study's deposit resolves only once that deposit exists
        // (not in a fresh clone): its law is checked in its overrides.
        for (const char* o : {"contact.tangential_model=\"blaze_tresca\"", "contact.rolling_model=\"angular_damping\"",
                              "contact.damping_model=\"restitution_blaze\"", "contact.reference_time_step=2e-08"})
          EXPECT_NE(std::find(set.begin(), set.end(), std::string(o)), set.end())
              << scale.name << ": " << o << " among " << fmt::format("{}", fmt::join(set, " "));
        continue;
      }
      Config c = Config::parse(resolved_case_configuration(seed.cases[k], scale, app::preset_directory()), "study");
      EXPECT_EQ(c.require_value_text("contact.tangential_model"), "\"blaze_tresca\"") << scale.name;
      EXPECT_EQ(c.require_value_text("contact.rolling_model"), "\"angular_damping\"") << scale.name;
      EXPECT_EQ(c.require_value_text("contact.damping_model"), "\"restitution_blaze\"") << scale.name;
      // The step the seed's k_n implies, but at the scale run at a ten times longer one.
      EXPECT_DOUBLE_EQ(c.get_double("contact.reference_time_step", 0.0),
                       scale.name.starts_with("demo-dtref2e-8") ? 2.0e-8 : 2.0e-9)
          << scale.name;
    }
    Config blaze =
        Config::parse(resolved_case_configuration(seed.cases[k], seed.scale("paper-fast"), app::preset_directory()), "study");
    Config textbook =
        Config::parse(resolved_case_configuration(ours.cases[k], ours.scale("paper-fast"), app::preset_directory()), "study");
    for (const char* key : {"contact.normal_stiffness", "contact.tangential_stiffness", "contact.static_friction",
                            "contact.kinetic_friction", "contact.rolling_friction", "contact.restitution",
                            "numerics.time_step_fraction", "pluviation.flow_rate", "pluviation.drop_height",
                            "pluviation.count", "trapdoor.rate", "trapdoor.travel", "spin_up.g_level"})
      EXPECT_EQ(blaze.require_value_text(key), textbook.require_value_text(key)) << seed.cases[k].name << " " << key;
  }
}

// The paper-box equal-density study (issue 36): each case is paper-table2's paper-fast case but for
// its start (a paper-fast Calibrated deposit, which a fresh clone does not hold, so the scale is
// resolved here without its [packing]) and, for rf1-epsd, the rolling model. Two scales, two
// deposits: pour seed 1's (paper-table2.toml) and pour seed 2's (paper-replicates.toml).
TEST(StudyDefinition, TheEqualDensityPaperStudyIsPaperFastFromTheCalibratedDeposits) {
  const fs::path studies = fs::path(TRAPDEM_SOURCE_DIR) / "studies";
  const StudyDefinition equal = load_study(studies / "equal-density-paper.toml");
  const StudyDefinition table2 = load_study(studies / "paper-table2.toml");
  ASSERT_EQ(equal.scales.size(), 2u);
  for (const auto& [scale_name, deposit] :
       {std::pair<std::string, std::string>{"paper-fast", "trapdem-out/paper-table2-paper-fast/cases/calibrated\""},
        {"paper-fast-seed2", "trapdem-out/paper-replicates-paper-fast/cases/calibrated/seed-2\""}}) {
    SCOPED_TRACE(scale_name);
    StudyScale scale = equal.scale(scale_name);
    std::vector<std::string>& set = scale.base.overrides;
    // The deposit's folder, made absolute beside the study file's folder.
    EXPECT_EQ(std::count_if(set.begin(), set.end(), [&](const std::string& o) {
                return o.starts_with("packing.from=") && o.ends_with(deposit);
              }), 1)
        << fmt::format("{}", fmt::join(set, " "));
    for (const char* o : {"packing.snapshot=1", "packing.start_stage=\"settling\""})
      EXPECT_NE(std::find(set.begin(), set.end(), std::string(o)), set.end()) << o;
    std::erase_if(set, [](const std::string& o) { return o.starts_with("packing."); });
    // The seed-2 deposit has two beads above the preset's 360 mm box: its box is 365 mm tall, a
    // bound of the domain only (the box's other keys are paper-table2's, compared below).
    const auto height = std::find(set.begin(), set.end(), std::string("box.height=0.365"));
    EXPECT_EQ(height != set.end(), scale_name == "paper-fast-seed2");
    if (height != set.end()) set.erase(height);
    auto resolved = [](const StudyDefinition& s, const std::string& name, const StudyScale& at) {
      const auto c = std::find_if(s.cases.begin(), s.cases.end(), [&](const StudyCase& k) { return k.name == name; });
      if (c == s.cases.end()) throw std::runtime_error(s.name + " has no case " + name);  // fails the test
      return Config::parse(resolved_case_configuration(*c, at, app::preset_directory()), name);
    };
    const StudyScale& fast = table2.scale("paper-fast");
    Config rf3 = resolved(equal, "rf3", scale), rf3_table2 = resolved(table2, "rf3", fast);
    Config rf1_epsd = resolved(equal, "rf1-epsd", scale), rf1_table2 = resolved(table2, "rf1", fast);
    for (const char* key : {"contact.normal_stiffness", "contact.tangential_stiffness", "contact.static_friction",
                            "contact.kinetic_friction", "contact.rolling_friction", "contact.restitution",
                            "contact.lever_arm", "numerics.time_step_fraction", "trapdoor.rate", "trapdoor.travel",
                            "spin_up.g_level", "box.depth_boundary", "box.height", "box.width", "box.depth"}) {
      EXPECT_EQ(rf3.require_value_text(key), rf3_table2.require_value_text(key)) << key;
      EXPECT_EQ(rf1_epsd.require_value_text(key), rf1_table2.require_value_text(key)) << key;
    }
    EXPECT_EQ(rf3.require_value_text("contact.rolling_model"), rf3_table2.require_value_text("contact.rolling_model"));
    EXPECT_EQ(rf1_epsd.require_value_text("contact.rolling_model"), "\"elastic_plastic\"");
    (void)ExperimentConfig::from(rf1_epsd);  // throws on any invalid key or value
  }
}

// The paper-box replicates (issue 36): Calibrated and RF3 resolved exactly as paper-table2's
// paper-fast cases, key for key, but for the pour seeds 2 and 3 (seed 1 is paper-table2's run).
TEST(StudyDefinition, ThePaperReplicatesArePaperTable2sPaperFastCasesWithSeedsTwoAndThree) {
  const fs::path studies = fs::path(TRAPDEM_SOURCE_DIR) / "studies";
  const StudyDefinition replicates = load_study(studies / "paper-replicates.toml");
  const StudyDefinition table2 = load_study(studies / "paper-table2.toml");
  const StudyScale& scale = replicates.scale("paper-fast");
  const StudyScale& fast = table2.scale("paper-fast");
  EXPECT_EQ(scale.replicates.seeds, (std::vector<std::uint64_t>{2, 3}));
  EXPECT_FALSE(fast.replicates.asked());
  ASSERT_EQ(replicates.cases.size(), 2u);
  for (const StudyCase& c : replicates.cases) {
    EXPECT_FALSE(c.replicates.asked()) << c.name;
    const auto twin = std::find_if(table2.cases.begin(), table2.cases.end(), [&](const StudyCase& k) { return k.name == c.name; });
    ASSERT_NE(twin, table2.cases.end()) << c.name;
    // The whole resolved configuration, as `trapdem run` would write it to resolved.toml.
    const std::string ours = resolved_case_configuration(c, scale, app::preset_directory());
    const std::string theirs = resolved_case_configuration(*twin, fast, app::preset_directory());
    EXPECT_EQ(ours, theirs) << c.name;
    Config config = Config::parse(ours, c.name);
    (void)ExperimentConfig::from(config);  // throws on any invalid key or value
  }
}

// The shape study (issue 39): four materials at one scale, each a valid run configuration; the
// beads and the rolling case are paper-table2's Calibrated and RF3 at the demo scale, rolling-epsd
// RF1 there with the elastic_plastic rolling model, the dimers the same box and law but for their
// shape, mu 0.5 and no rolling resistance.
TEST(StudyDefinition, TheShapeStudyIsBeadsTwoRollingResistancesAndDimersInOneBox) {
  const fs::path studies = fs::path(TRAPDEM_SOURCE_DIR) / "studies";
  const StudyDefinition shape = load_study(studies / "shape.toml");
  const StudyDefinition table2 = load_study(studies / "paper-table2.toml");
  ASSERT_EQ(shape.cases.size(), 4u);
  for (const StudyScale& scale : shape.scales) {
    for (const StudyCase& c : shape.cases) {
      Config config = Config::parse(resolved_case_configuration(c, scale, app::preset_directory()), c.name);
      const ExperimentConfig run = ExperimentConfig::from(config);  // throws on any invalid key
      EXPECT_EQ(run.material.shape.is_clump(), c.name == "dimers") << c.name << " at " << scale.name;
    }
  }
  const StudyScale& demo = shape.scale("demo-seeds");
  EXPECT_EQ(demo.replicates.count, 3);
  auto resolved = [&](const StudyDefinition& s, std::size_t k, const StudyScale& scale) {
    return Config::parse(resolved_case_configuration(s.cases[k], scale, app::preset_directory()), "study");
  };
  Config beads = resolved(shape, 0, demo), rolling = resolved(shape, 1, demo), rolling_epsd = resolved(shape, 2, demo),
         dimers = resolved(shape, 3, demo);
  Config calibrated = resolved(table2, 0, table2.scale("demo")), rf1 = resolved(table2, 1, table2.scale("demo")),
         rf3 = resolved(table2, 3, table2.scale("demo"));
  for (const char* key : {"contact.static_friction", "contact.kinetic_friction", "contact.rolling_friction",
                          "contact.rolling_model", "contact.normal_stiffness", "box.width", "pluviation.count",
                          "particles.min_diameter", "trapdoor.travel"}) {
    EXPECT_EQ(beads.require_value_text(key), calibrated.require_value_text(key)) << key;
    EXPECT_EQ(rolling.require_value_text(key), rf3.require_value_text(key)) << key;
    // RF1's friction with the rolling spring that holds its torque at rest (issue 36's model).
    if (std::string(key) != "contact.rolling_model")
      EXPECT_EQ(rolling_epsd.require_value_text(key), rf1.require_value_text(key)) << key;
  }
  EXPECT_EQ(rolling_epsd.require_value_text("contact.rolling_model"), "\"elastic_plastic\"");
  EXPECT_EQ(dimers.require_value_text("contact.kinetic_friction"), "0.5");
  EXPECT_EQ(dimers.require_value_text("contact.rolling_friction"), "0.0");
  for (const char* key : {"contact.normal_stiffness", "contact.restitution", "box.width", "box.depth",
                          "pluviation.count", "particles.min_diameter", "particles.max_diameter", "trapdoor.rate"})
    EXPECT_EQ(dimers.require_value_text(key), calibrated.require_value_text(key)) << key;
}

// A relative packing.from under a case's `set` names a file beside the study file (as the scale's
// `config` does), whatever the working folder, which here holds another packing of the same name:
// the case's runs get the path absolute, and the packing read is the study folder's (3 spheres,
// not the working folder's 2).
TEST(StudyDefinition, RelativePackingUnderSetIsTheStudyFilesFolder) {
  const test::ScratchDir scratch("trapdem-study-packing");
  const fs::path& dir = scratch.path();
  fs::create_directories(dir / "studies");
  fs::create_directories(dir / "work");
  auto dump = [](const fs::path& path, int count) {
    std::ofstream out(path);
    out << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n" << count << "\nITEM: ATOMS id x y z radius\n";
    for (int k = 0; k < count; ++k) out << k + 1 << " " << 0.01 + 0.01 * k << " 0.007 0.0022 0.002\n";
  };
  dump(dir / "studies" / "bed.dump", 3);
  dump(dir / "work" / "bed.dump", 2);
  std::ofstream(dir / "studies" / "study.toml") << "name = \"from-a-packing\"\n[scales.small]\npreset = \"tiny\"\n"
                                                   "[cases.packed.set.packing]\nfrom = \"bed.dump\"\n"
                                                   "format = \"lammps-dump\"\n";
  const fs::path before = fs::current_path();
  fs::current_path(dir / "work");
  const std::string absolute = (dir / "studies" / "bed.dump").lexically_normal().string();
  try {
    const StudyDefinition s = load_study("../studies/study.toml");
    ASSERT_EQ(s.cases.size(), 1u);
    const std::vector<std::string>& set = s.cases[0].own.overrides;
    EXPECT_NE(std::find(set.begin(), set.end(), "packing.from=" + trapdem::quoted(absolute)), set.end());
    const std::string resolved = resolved_case_configuration(s.cases[0], s.scales[0], app::preset_directory());
    EXPECT_NE(resolved.find("from = \"" + absolute + "\""), std::string::npos) << resolved;
    EXPECT_NE(resolved.find("packing_particle_count = 3"), std::string::npos) << resolved;
  } catch (...) {
    fs::current_path(before);
    throw;
  }
  fs::current_path(before);
}
