// The default experiment end to end, as `make demo` runs it: `trapdem run --preset demo` (about
// 14 000 spheres poured, settled, spun up to 50 g, the trapdoor lowered 20 mm = 0.4 B) and then
// `trapdem analyze`. The checks are the trapdoor mechanism the paper describes (Terzaghi's
// arching; shear bands from the trapdoor's edges; a zone of influence at the surface) and the
// bookkeeping of loads, on the files a user reads (trapdoor.csv, analysis/metrics.json: the formats
// of docs/output.md and docs/analysis.md). Minutes on two cores: labelled slow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs the trapdem command with `arguments`; its output goes to `log`. Returns the exit status.
int trapdem(const std::string& arguments, const fs::path& log) {
  const std::string command = std::string("'") + TRAPDEM_EXECUTABLE + "' " + arguments + " > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// trapdoor.csv as columns by header name.
std::map<std::string, std::vector<double>> read_csv_columns(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> columns;
  if (!std::getline(in, line)) return columns;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t k = 0; k < names.size() && std::getline(row, cell, ','); ++k)
      columns[names[k]].push_back(std::stod(cell));
  }
  return columns;
}

// The number after the keys `path` met in that order in a JSON text (each key searched after the
// previous one): enough for metrics.json, whose keys at each level are distinct. NaN when a key is
// missing or the value is null.
double json_number(const std::string& text, const std::vector<std::string>& path) {
  std::size_t at = 0;
  for (const std::string& key : path) {
    at = text.find("\"" + key + "\"", at);
    if (at == std::string::npos) return std::nan("");
    at += key.size() + 2;
  }
  at = text.find(':', at);
  if (at == std::string::npos) return std::nan("");
  const char* start = text.c_str() + at + 1;
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  return end == start ? std::nan("") : value;
}

TEST(DemoPipelineSlow, RunAndAnalyzeShowArchingShearBandsAndAZoneOfInfluence) {
  const fs::path dir = fs::temp_directory_path() / "trapdem-demo-pipeline-test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path run = dir / "demo";
  ASSERT_EQ(trapdem("run --preset demo --quiet --out '" + run.string() + "'", dir / "run.out"), 0)
      << read_text(dir / "run.out");
  EXPECT_NE(read_text(run / "run.log").find("\nfinished"), std::string::npos) << "run.log has no 'finished' line";
  ASSERT_EQ(trapdem("analyze '" + run.string() + "' --quiet", dir / "analyze.out"), 0) << read_text(dir / "analyze.out");

  const double B = 0.05;       // m, trapdoor width (presets/demo.toml)
  const double travel = 0.02;  // m
  auto grc = read_csv_columns(run / "trapdoor.csv");
  const auto& delta = grc["trapdoor_displacement_m"];
  const auto& ratio = grc["trapdoor_stress_ratio"];
  const auto& trapdoor_force = grc["trapdoor_force_N"];
  const auto& left_force = grc["base_left_force_N"];
  const auto& right_force = grc["base_right_force_N"];
  // One row at the start, one each 0.5 mm (output.ground_reaction_step) and one at the end.
  ASSERT_GE(delta.size(), 40u);
  ASSERT_EQ(ratio.size(), delta.size());
  ASSERT_EQ(left_force.size(), delta.size());
  EXPECT_NEAR(delta.back(), travel, 1e-4);

  // Before lowering the trapdoor carries the stress of the base beside it: it is part of the base.
  const double base_width = (0.25 - B) / 2;  // m, each side
  const double trapdoor_stress_over_base = (trapdoor_force[0] / B) / ((left_force[0] + right_force[0]) / (2 * base_width));
  std::printf("[ measured ] before lowering: trapdoor stress / base stress %.3f\n", trapdoor_stress_over_base);
  EXPECT_NEAR(trapdoor_stress_over_base, 1.0, 0.35);

  // Arching (Terzaghi 1936; the paper's ground reaction curves): the trapdoor's load falls to a
  // small fraction of its initial value within a few per cent of B, then recovers somewhat as the
  // mechanism becomes a sliding column.
  std::size_t least = 0;
  for (std::size_t k = 0; k < ratio.size(); ++k)
    if (ratio[k] < ratio[least]) least = k;
  std::printf("[ measured ] least trapdoor load ratio %.3f at delta/B %.3f; final %.3f\n", ratio[least],
              delta[least] / B, ratio.back());
  EXPECT_LT(ratio[least], 0.35);
  EXPECT_LT(delta[least] / B, 0.15);
  EXPECT_GT(ratio.back(), ratio[least]);

  // The load the trapdoor sheds goes to the base beside it: trapdoor + base carry the same total
  // before and at the end (the side walls' friction takes a part that changes little).
  const double total_before = trapdoor_force.front() + left_force.front() + right_force.front();
  const double total_after = trapdoor_force.back() + left_force.back() + right_force.back();
  std::printf("[ measured ] trapdoor + base load: %.1f N before, %.1f N at the end\n", total_before, total_after);
  EXPECT_NEAR(total_after / total_before, 1.0, 0.1);

  // The analysis: shear bands rise from both edges of the trapdoor, and the surface settles over a
  // zone wider than the trapdoor.
  const std::string metrics = read_text(run / "analysis" / "metrics.json");
  ASSERT_FALSE(metrics.empty()) << "no analysis/metrics.json";
  const double left_angle = json_number(metrics, {"shear_bands", "left", "angle_deg"});
  const double right_angle = json_number(metrics, {"shear_bands", "right", "angle_deg"});
  const double left_height = json_number(metrics, {"shear_bands", "left", "height_reached_over_B"});
  const double zone_surface = json_number(metrics, {"zone_of_influence", "surface_width_over_B"});
  std::printf("[ measured ] band angles %.1f / %.1f deg from the vertical, left band height %.2f B; "
              "surface zone %.2f B\n",
              left_angle, right_angle, left_height, zone_surface);
  EXPECT_TRUE(std::isfinite(left_angle) && std::isfinite(right_angle)) << "a shear band was not found";
  EXPECT_GT(zone_surface, 1.0);
  fs::remove_all(dir);
}

}  // namespace
