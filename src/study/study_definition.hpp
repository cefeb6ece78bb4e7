#pragma once
// A study: a list of trapdoor cases run one after another and reported together (`trapdem study`).
//
// A study file (TOML, docs/study.md) names its scales and its cases. A scale is the base every case
// starts from at that size (a preset or a configuration file, plus overrides): the paper's strongbox,
// or the demo's scaled box. A case is what makes it differ (overrides, nested as in a run's
// configuration; optionally its own base). So `--scale demo` runs the same cases in minutes that
// `--scale paper` runs in days.
//
//   name = "paper-table2"
//   default_scale = "demo"
//   [scales.demo]
//   preset = "demo"
//   [cases.rf1]
//   label = "RF1"
//   [cases.rf1.set.contact]
//   kinetic_friction = 0.2
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "study/replicates.hpp"

namespace trapdem {

class Config;

// Where a configuration comes from: a preset by name or a file, then overrides ("key=value").
struct ConfigRecipe {
  std::string preset;                  // a preset name, or empty
  std::filesystem::path config;        // a configuration file (absolute), or empty
  std::vector<std::string> overrides;  // applied in order on top of the base
};

struct StudyScale {
  std::string name;
  std::string description;
  ConfigRecipe base;
  ReplicateRequest replicates;         // `replicates`/`seeds` in the scale's table (study/replicates.hpp)
};

struct StudyCase {
  std::string name;                    // the folder name: letters, digits, '-', '_', '.'
  std::string label;                   // for tables and figures (default: the name)
  ConfigRecipe own;                    // preset/config replace the scale's base if given
  ReplicateRequest replicates;         // `replicates`/`seeds` in the case's table
};

struct StudyReportSettings {
  double contours_at = 0.01;           // m of trapdoor travel for the vertical displacement contours
  double angle_of_draw_deg = 30.0;     // the supposition's angle beside each case's DEM estimate
  double max_strain = 0.0;             // top of the shared gamma_max scale; 0: automatic
  // The virtual element test of each case's particles and contact law (`trapdem element`, issue 17),
  // once per case: phi'_peak and phi'_cs beside the mechanism metrics.
  bool element_test = false;
  std::vector<std::string> element_overrides;  // [report.element] as "element.KEY=value" overrides
};

struct StudyDefinition {
  std::string name;
  std::string description;
  std::string default_scale;
  std::vector<StudyScale> scales;      // in the order the file writes them
  std::vector<StudyCase> cases;        // in the order the file writes them
  StudyReportSettings report;
  ReplicateRequest replicates;         // `replicates`/`seeds` at the file's top level
  std::filesystem::path source;        // the study file ("" if built in code)

  // Throws InputError naming the study file and listing the scales if `name` is not one of them.
  const StudyScale& scale(const std::string& name) const;
};

// Upper bounds of a study file (docs/study.md): cases, and runs at one scale (each case times its
// replicates, study/replicates.hpp bounds those).
inline constexpr std::size_t kMaxCases = 1000;
inline constexpr std::int64_t kMaxRuns = 10000;

// Reads a study file strictly (unknown keys reported with file:line). Relative configuration paths
// are taken from the study file's folder. Throws InputError / FileError.
StudyDefinition load_study(const std::filesystem::path& file);

// The recipe a case runs with at a scale: the case's base if it has one, else the scale's; the scale's
// overrides, then the case's, then name = the case name.
ConfigRecipe case_recipe(const StudyCase& study_case, const StudyScale& scale);

// The replicate request that applies to a case at a scale (case, else scale, else study).
const ReplicateRequest& case_replicates(const StudyDefinition& study, const StudyCase& study_case,
                                        const StudyScale& scale);

// A folder-safe case name ("rolling_friction-0.2"): letters, digits, '-', '_', '.'; not empty, not "."/"..".
bool is_valid_case_name(const std::string& name);

// Every value under `table` ("" for the whole document), recursively, as (dotted key relative to the
// table, TOML text of the value) in document order, each marked as used.
std::vector<std::pair<std::string, std::string>> flatten_values(Config& document, const std::string& table);
// The same as "dotted.key=toml-value" overrides.
std::vector<std::string> overrides_from_table(Config& document, const std::string& table);

}  // namespace trapdem
