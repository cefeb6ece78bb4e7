// `trapdem element` itself (apps/element_command.cpp) on a very small specimen: the files it
// writes and their contents, and the bad inputs the command refuses before any simulation.
// The physics of the test is in element_test.cpp (fast) and slow/element_slow_test.cpp.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <omp.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "element_command.hpp"
#include "element_test_config.hpp"
#include "io/text_file.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;

namespace trapdem {
namespace {

// The shared element-test configuration (mu = 0.3) as a file; `element_keys` go into its [element].
fs::path write_config(const fs::path& dir, const std::string& element_keys) {
  const fs::path file = dir / "element.toml";
  std::ofstream(file) << element_test_config("element-command", 0.3, 0.0) << element_keys;
  return file;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

Csv read_csv(const fs::path& file) {
  Csv csv;
  std::istringstream in(read_text_file(file));
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cs(line);
    std::string cell;
    while (std::getline(cs, cell, ',')) cells.push_back(cell);
    if (first) csv.header = cells;
    else csv.rows.push_back(cells);
    first = false;
  }
  return csv;
}

// 100 spheres sheared to 2 % at I = 5e-3: a few seconds, enough for the files to carry every
// field (the angles of so small a specimen mean little; the bounds below are only sanity).
TEST(ElementCommand, WritesTheCsvTheJsonAndTheFigureOfBothSpecimens) {
  const int threads = omp_get_max_threads();
  const test::ScratchDir scratch("trapdem-element-command-files");
  const fs::path& dir = scratch.path();
  app::ElementOptions o;
  o.config_file = write_config(dir, "particles = 100\n"
                                    "inertial_number = 5e-3\n"
                                    "max_axial_strain = 0.02\n"
                                    "critical_state_window = 0.01\n"
                                    "row_strain = 0.0025\n")
                      .string();
  o.confining = {40e3};
  o.out_dir = (dir / "out").string();
  o.threads = 1;
  o.quiet = true;
  ASSERT_EQ(app::run_element(o), 0);
  omp_set_num_threads(threads);

  for (const char* name : {"element.csv", "element.json", "element.png", "element.log", "resolved.toml"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
  // A PNG, and not a blank one: its compressed size grows with what is drawn (an empty canvas of
  // this size compresses to a few kB).
  const std::string png = read_text_file(dir / "out" / "element.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_GT(png.size(), 10000u);
  // The option went through the configuration: resolved.toml records it.
  EXPECT_NE(read_text_file(dir / "out" / "resolved.toml").find("confining = [40000"), std::string::npos);

  const Csv csv = read_csv(dir / "out" / "element.csv");
  const std::size_t packing = csv.column("packing"), confining = csv.column("confining_Pa"),
                    strain = csv.column("axial_strain"), sin_phi = csv.column("sin_phi_mobilised"),
                    sxx = csv.column("wall_sxx_Pa"), cxx = csv.column("contact_sxx_Pa"),
                    inertial = csv.column("inertial_number");
  int dense = 0, loose = 0;
  for (const auto& row : csv.rows) {
    ASSERT_EQ(row.size(), csv.header.size());
    (row[packing] == "dense" ? dense : loose) += 1;
    EXPECT_EQ(std::stod(row[confining]), 40e3);
    const double s = std::stod(row[sin_phi]);
    EXPECT_GT(s, 0.0);
    EXPECT_LT(s, 1.0);
    EXPECT_GT(std::stod(row[strain]), 0.0);
    EXPECT_LE(std::stod(row[strain]), 0.021);
    // The servo axis holds the confining stress (a 100-sphere specimen: 5 %), and the contact
    // stress follows the wall stress (the specimen's inertia separates them: 20 %).
    EXPECT_NEAR(std::stod(row[sxx]) / 40e3, 1.0, 0.05);
    EXPECT_NEAR(std::stod(row[cxx]) / std::stod(row[sxx]), 1.0, 0.2);
    EXPECT_NEAR(std::stod(row[inertial]), 5e-3, 2e-3);
  }
  // 2 % in rows of 0.25 %: 8 rows each (the last may close early).
  EXPECT_GE(dense, 7);
  EXPECT_LE(dense, 9);
  EXPECT_EQ(dense, loose);

  const Json json = Json::parse(read_text_file(dir / "out" / "element.json"), "element.json");
  EXPECT_EQ(json["configuration"].as_string(), "element-command");
  EXPECT_EQ(json["test"].as_string(), "biaxial");
  EXPECT_EQ(json["particles"].as_number(), 100.0);
  ASSERT_EQ(json["specimens"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const Json& s = json["specimens"][k];
    EXPECT_EQ(s["packing"].as_string(), k == 0 ? "dense" : "loose");
    EXPECT_GT(s["initial_solid_fraction"].as_number(), 0.45);
    EXPECT_LT(s["initial_solid_fraction"].as_number(), 0.66);
    EXPECT_NEAR(s["initial_void_ratio"].as_number(), 1.0 / s["initial_solid_fraction"].as_number() - 1.0, 1e-4);
    EXPECT_NEAR(s["isotropic_contact_over_wall_mean_stress"].as_number(), 1.0, 0.02);
    EXPECT_GT(s["phi_peak_deg"].as_number(), 0.0);
    EXPECT_LT(s["phi_peak_deg"].as_number(), 60.0);
    EXPECT_LE(s["phi_cs_deg"].as_number(), s["phi_peak_deg"].as_number() + 1e-9);
  }
  ASSERT_EQ(json["angles"].size(), 1u);
  EXPECT_EQ(json["angles"][0]["confining_Pa"].as_number(), 40e3);
  // The material's phi'_cs is the mean of the dense and loose specimens'.
  EXPECT_NEAR(json["angles"][0]["phi_cs_deg"].as_number(),
              0.5 * (json["specimens"][0]["phi_cs_deg"].as_number() + json["specimens"][1]["phi_cs_deg"].as_number()),
              1e-4);
}

std::string error_of(const app::ElementOptions& o) {
  try {
    app::run_element(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ElementCommand, RefusesANonPositiveConfiningStressAndAConfigurationWithoutParticles) {
  const test::ScratchDir scratch("trapdem-element-command-bad");
  const fs::path& dir = scratch.path();
  app::ElementOptions o;
  o.config_file = write_config(dir, "particles = 100\n").string();
  o.out_dir = (dir / "out").string();
  o.quiet = true;
  for (double p : {0.0, -5e4}) {
    o.confining = {p};
    const std::string message = error_of(o);
    EXPECT_NE(message.find("element.confining"), std::string::npos) << message;
    EXPECT_NE(message.find("expected a number in (0, "), std::string::npos) << message;
  }
  // Nothing was run: no element.json.
  EXPECT_FALSE(fs::exists(dir / "out" / "element.json"));

  o.confining.clear();
  const fs::path bare = dir / "bare.toml";
  std::ofstream(bare) << "name = \"no-particles\"\n[contact]\nstatic_friction = 0.3\n";
  o.config_file = bare.string();
  const std::string message = error_of(o);
  EXPECT_NE(message.find("bare.toml"), std::string::npos) << message;
  EXPECT_NE(message.find("no [particles] table"), std::string::npos) << message;
}

}  // namespace
}  // namespace trapdem
