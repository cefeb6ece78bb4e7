#include "study/study_definition.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/text_escape.hpp"
#include "io/config.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// A base (preset or config file) and the overrides under `set`, from a scale's or a case's table.
ConfigRecipe read_recipe(Config& document, const std::string& table, const fs::path& study_folder) {
  ConfigRecipe recipe;
  recipe.preset = document.get_string(table + ".preset", "");
  const std::string config = document.get_string(table + ".config", "");
  if (!recipe.preset.empty() && !config.empty())
    throw document.error(table + ".config", "either preset or config, not both");
  if (!config.empty()) {
    recipe.config = fs::path(config).is_absolute() ? fs::path(config) : study_folder / config;
    if (!fs::exists(recipe.config))
      throw document.error(table + ".config", fmt::format("an existing configuration file ({} not found)",
                                                          recipe.config.string()));
  }
  if (document.has(table + ".set")) {
    if (!document.is_table(table + ".set"))
      throw document.error(table + ".set", "a table of configuration keys, e.g. [" + table + ".set.contact]");
    recipe.overrides = overrides_from_table(document, table + ".set");
    // A relative packing.from under `set` names a file beside the study file, as `config` does
    // (Config::require_path: the study file's folder); the runs get it absolute.
    const std::string from = table + ".set.packing.from";
    if (document.has(from)) {
      const std::string path = document.require_path(from);
      for (std::string& o : recipe.overrides)
        if (o.rfind("packing.from=", 0) == 0) o = "packing.from=" + trapdem::quoted(path);
    }
  }
  return recipe;
}

}  // namespace

bool is_valid_case_name(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  return true;
}

std::vector<std::pair<std::string, std::string>> flatten_values(Config& document, const std::string& table) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& key : document.keys(table)) {
    const std::string full = table.empty() ? key : table + "." + key;
    if (document.is_table(full)) {
      for (auto& [inner, value] : flatten_values(document, full)) out.emplace_back(key + "." + inner, std::move(value));
    } else {
      out.emplace_back(key, document.require_value_text(full));
    }
  }
  return out;
}

std::vector<std::string> overrides_from_table(Config& document, const std::string& table) {
  std::vector<std::string> out;
  for (const auto& [key, value] : flatten_values(document, table)) out.push_back(key + "=" + value);
  return out;
}

const StudyScale& StudyDefinition::scale(const std::string& wanted) const {
  std::string known;
  for (const StudyScale& s : scales) {
    if (s.name == wanted) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw InputError(fmt::format("{}: no scale named '{}' (the study has: {})",
                               source.empty() ? name : source.string(), wanted, known));
}

StudyDefinition load_study(const fs::path& file) {
  Config document = Config::load_file(file.string());
  const fs::path folder = fs::absolute(file).parent_path();
  StudyDefinition study;
  study.source = file;
  study.name = document.get_string("name", file.stem().string());
  study.description = document.get_string("description", "");
  study.replicates = read_replicate_request(document, "");

  if (!document.is_table("scales")) throw document.error("scales", "a table of scales, e.g. [scales.demo] preset = \"demo\"");
  for (const std::string& name : document.keys("scales")) {
    const std::string table = "scales." + name;
    if (!document.is_table(table)) throw document.error(table, "a table (preset, config, description, set)");
    StudyScale scale;
    scale.name = name;
    scale.description = document.get_string(table + ".description", "");
    scale.base = read_recipe(document, table, folder);
    scale.replicates = read_replicate_request(document, table);
    if (scale.base.preset.empty() && scale.base.config.empty())
      throw document.error(table, "a preset or a config: the base every case starts from at this scale");
    study.scales.push_back(std::move(scale));
  }
  study.default_scale = document.get_string("default_scale", study.scales.front().name);
  study.scale(study.default_scale);  // must exist

  if (!document.is_table("cases")) throw document.error("cases", "a table of cases, e.g. [cases.calibrated]");
  for (const std::string& name : document.keys("cases")) {
    const std::string table = "cases." + name;
    if (!is_valid_case_name(name))
      throw document.error(table, "a case name usable as a folder name (letters, digits, '-', '_', '.')");
    if (!document.is_table(table)) throw document.error(table, "a table (label, preset, config, set)");
    StudyCase c;
    c.name = name;
    c.label = document.get_string(table + ".label", name);
    c.own = read_recipe(document, table, folder);
    c.replicates = read_replicate_request(document, table);
    study.cases.push_back(std::move(c));
  }
  if (study.cases.empty()) throw document.error("cases", "at least one case");
  // Every case is a whole run per replicate, listed in every table and figure of the report: a
  // grid of cases past these bounds is a slip (a generated file gone wrong), not a study.
  if (study.cases.size() > kMaxCases)
    throw document.error("cases", fmt::format("at most {} cases (a run each, each in the report), not {}", kMaxCases,
                                              study.cases.size()));
  for (const StudyScale& scale : study.scales) {
    std::int64_t runs = 0;
    for (const StudyCase& c : study.cases) runs += std::max<std::int64_t>(1, case_replicates(study, c, scale).count);
    if (runs > kMaxRuns)
      throw document.error("scales." + scale.name,
                           fmt::format("at most {} runs at a scale (cases times replicates), not {}", kMaxRuns, runs));
  }

  // Bounds as trapdoor.travel's (docs/config.md) and a gamma_max colour scale up to 1000 %.
  study.report.contours_at = document.get_double("report.contours_at", 0.01, "m", Range::open_closed(0.0, 10.0));
  study.report.angle_of_draw_deg = document.get_double("report.angle_of_draw", 30.0, "degrees from the vertical",
                                                       {0.0, 90.0, true, false});
  study.report.max_strain = document.get_double("report.max_strain", 0.0, "-", Range::closed(0.0, 10.0));
  study.report.element_test = document.get_bool("report.element_test", false);
  if (document.has("report.element")) {
    if (!document.is_table("report.element"))
      throw document.error("report.element", "a table of element-test keys, e.g. particles = 300 (docs/element.md)");
    // Checked when each case's element setup is read, before the first run (study_runner).
    for (const auto& [key, value] : flatten_values(document, "report.element"))
      study.report.element_overrides.push_back("element." + key + "=" + value);
    if (!study.report.element_test)
      throw document.error("report.element", "report.element_test = true (the table sets an element test that "
                                             "would not run)");
  }
  document.report_unused();
  return study;
}

const ReplicateRequest& case_replicates(const StudyDefinition& study, const StudyCase& study_case,
                                        const StudyScale& scale) {
  return applicable_request(study_case.replicates, scale.replicates, study.replicates);
}

ConfigRecipe case_recipe(const StudyCase& study_case, const StudyScale& scale) {
  ConfigRecipe recipe = scale.base;
  if (!study_case.own.preset.empty() || !study_case.own.config.empty()) {
    recipe.preset = study_case.own.preset;
    recipe.config = study_case.own.config;
  }
  recipe.overrides.insert(recipe.overrides.end(), study_case.own.overrides.begin(), study_case.own.overrides.end());
  recipe.overrides.push_back(fmt::format("name=\"{}\"", study_case.name));
  return recipe;
}

}  // namespace trapdem
