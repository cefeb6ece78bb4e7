#include "study/calibration.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "core/length_text.hpp"
#include "core/errors.hpp"
#include "core/trimmed.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"
#include "plot/error_surface.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_record.hpp"
#include "plot/figure_format.hpp"
#include "study/run_comparison.hpp"
#include "study/study_definition.hpp"
#include "study/study_runner.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// A value as part of a folder name: quotes dropped, anything else unsafe as '-'.
std::string name_part(const std::string& value) {
  std::string out;
  for (char c : value) {
    if (c == '"' || c == '\'') continue;
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '-';
  }
  return out;
}

std::string last_component(const std::string& key) { return key.substr(key.rfind('.') + 1); }

// Every combination of the values, the first key varying fastest.
std::vector<std::vector<std::size_t>> grid_indices(const std::vector<VariedKey>& keys) {
  std::vector<std::vector<std::size_t>> out{{}};
  for (const VariedKey& k : keys) {
    std::vector<std::vector<std::size_t>> next;
    for (std::size_t v = 0; v < k.values.size(); ++v)
      for (const auto& partial : out) {
        auto combination = partial;
        combination.push_back(v);
        next.push_back(std::move(combination));
      }
    out = std::move(next);
  }
  return out;
}

StudyDefinition calibration_study(const CalibrateOptions& o, const std::vector<VariedKey>& keys) {
  StudyDefinition study;
  const fs::path base = fs::absolute(o.base);
  study.name = "calibrate-" + base.stem().string();
  study.description = fmt::format("Calibration of {} against the PIV in {} at {}", base.filename().string(), o.target,
                                  o.at);
  StudyScale scale;
  scale.name = "base";
  scale.description = base.string();
  scale.base.config = base;
  study.scales.push_back(scale);
  study.default_scale = "base";
  // Short names unless two varied keys end alike.
  std::set<std::string> last;
  for (const VariedKey& k : keys) last.insert(last_component(k.key));
  const bool short_names = last.size() == keys.size();
  for (const auto& combination : grid_indices(keys)) {
    StudyCase c;
    std::string label;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string& value = keys[i].values[combination[i]];
      std::string key_name = short_names ? last_component(keys[i].key) : keys[i].key;
      std::replace(key_name.begin(), key_name.end(), '.', '-');
      c.name += (i ? "_" : "") + key_name + "-" + name_part(value);
      label += fmt::format("{}{} = {}", i ? ", " : "", last_component(keys[i].key), value);
      c.own.overrides.push_back(keys[i].key + "=" + value);
    }
    if (!is_valid_case_name(c.name)) c.name = fmt::format("case-{:03d}", study.cases.size() + 1);
    c.label = label;
    study.cases.push_back(std::move(c));
  }
  study.report.contours_at = parse_length(o.at, "--at");
  return study;
}

std::string rows_csv(const Calibration& c) {
  std::string out = "rank,case";
  // Appended piece by piece: `out += "," + x` trips GCC 12's false -Wrestrict (GCC bug 105651).
  for (const VariedKey& k : c.keys) {
    out += ',';
    out += k.key;
  }
  out += ",rms_over_delta,bias_over_delta,coverage\n";
  for (std::size_t r = 0; r < c.ranked.size(); ++r) {
    const CalibrationRow& row = c.ranked[r];
    out += fmt::format("{},{}", r + 1, row.case_name);
    for (const std::string& v : row.values) {
      out += ',';
      out += name_part(v);
    }
    out += fmt::format(",{:.6g},{:.6g},{:.4f}\n", row.error, row.bias, row.coverage);
  }
  return out;
}

// The surface over the first two keys (at the best case's values of any others).
plot::ErrorSurface error_surface(const Calibration& c, const std::vector<std::vector<std::size_t>>& grid,
                                 const std::vector<double>& error_of_case, const std::string& at) {
  plot::ErrorSurface s;
  s.error_label = "RMS(w_DEM - w_PIV) / δ (%)";
  s.error_scale = 100.0;
  s.title = fmt::format("Calibration error at δ = {}", format_mm(parse_length(at, "--at")));
  s.x_key = c.keys[0].key;
  s.x_values = c.keys[0].values;
  const std::size_t nx = c.keys[0].values.size();
  std::size_t ny = 1;
  if (c.keys.size() >= 2) {
    s.y_key = c.keys[1].key;
    s.y_values = c.keys[1].values;
    ny = s.y_values.size();
  }
  s.error.assign(nx * ny, std::nan(""));
  // The best case's grid position fixes the keys beyond the second.
  std::vector<std::size_t> best_at;
  for (std::size_t k = 0; k < grid.size(); ++k)
    if (!c.ranked.empty() && error_of_case[k] == c.ranked.front().error) best_at = grid[k];
  std::string fixed;
  for (std::size_t i = 2; i < c.keys.size(); ++i)
    fixed += fmt::format("{}{} = {}", fixed.empty() ? "" : ", ", c.keys[i].key, c.keys[i].values[best_at[i]]);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    bool on_slice = true;
    for (std::size_t i = 2; i < c.keys.size(); ++i) on_slice = on_slice && grid[k][i] == best_at[i];
    if (on_slice) s.error[(c.keys.size() >= 2 ? grid[k][1] : 0) * nx + grid[k][0]] = error_of_case[k];
  }
  s.subtitle = fmt::format("{} cases; best outlined: {}{}", grid.size(), c.ranked.front().case_name,
                           fixed.empty() ? "" : "; slice at " + fixed);
  return s;
}

}  // namespace

VariedKey parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || trimmed(text.substr(0, eq)).empty())
    throw InputError(fmt::format("--vary '{}': expected KEY=V1,V2,... (e.g. contact.rolling_friction=0.1,0.2)", text));
  VariedKey v;
  v.key = trimmed(text.substr(0, eq));
  std::size_t start = eq + 1;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string value = trimmed(text.substr(start, end - start));
    if (value.empty()) throw InputError(fmt::format("--vary '{}': an empty value", text));
    if (std::find(v.values.begin(), v.values.end(), value) != v.values.end())
      throw InputError(fmt::format("--vary '{}': the value {} is given twice", text, value));
    v.values.push_back(value);
    start = end + 1;
  }
  return v;
}

CalibrationGrid calibration_grid(const CalibrateOptions& o) {
  if (o.vary.empty()) throw InputError("trapdem calibrate: give at least one --vary KEY=V1,V2,...");
  CalibrationGrid grid;
  for (const std::string& text : o.vary) {
    VariedKey k = parse_vary(text);
    for (const VariedKey& other : grid.keys)
      if (other.key == k.key) throw InputError(fmt::format("--vary: the key {} is varied twice", k.key));
    grid.keys.push_back(std::move(k));
  }
  if (!fs::exists(fs::path(o.target) / "piv.h5") && !fs::is_regular_file(o.target))
    throw InputError(fmt::format("--target {}: no piv.h5 there (run `trapdem piv ... --out {}` first)", o.target, o.target));
  grid.study = calibration_study(o, grid.keys);
  grid.out = o.out.empty() ? fs::path("trapdem-out") / grid.study.name : fs::path(o.out);
  return grid;
}

Calibration calibrate(const CalibrateOptions& o) {
  const plot::FigureFormat format = plot::parse_figure_format(o.format, "--format");
  const CalibrationGrid calibration = calibration_grid(o);
  Calibration result;
  result.keys = calibration.keys;
  result.out = calibration.out;
  const StudyDefinition& study = calibration.study;
  const StudyScale& scale = study.scales.front();
  if (o.collect) {
    // The grid ran elsewhere (a Slurm array): rank it only when every case is there.
    if (!holds_study(result.out)) throw InputError(fmt::format("--collect: {} holds no calibration", result.out.string()));
    claim_study_folder(study, scale, result.out);
    std::string missing;
    for (const StudyCase& c : study.cases)
      if (!run_finished(RunFolder(case_directory(result.out, c))))
        missing += (missing.empty() ? "" : ", ") + c.name;
    if (!missing.empty())
      throw InputError(fmt::format("--collect: the grid in {} is not complete ({} not finished: see --status); "
                                   "submit or run it again to resume them, then rank", result.out.string(), missing));
  } else if (!run_study_in_folder(study, scale, result.out, StudyRunSettings{{}, o.threads, o.quiet, {}})) {
    // A study's folder rules: resumable, a changed case refused, another study's folder refused.
    // Its cases name no preset (the scale's base is the file), so no preset folder is needed.
    return result;
  }
  result.complete = true;

  const auto grid = grid_indices(result.keys);
  std::vector<double> error_of_case(study.cases.size(), std::nan(""));
  std::vector<CompareResult> compared;
  for (std::size_t k = 0; k < study.cases.size(); ++k) {
    CompareOptions c;
    c.dem_dir = case_directory(result.out, study.cases[k]).string();
    c.piv_dir = o.target;
    c.at = o.at;
    c.grid = o.grid;
    c.piv_trapdoor = o.piv_trapdoor;
    compared.push_back(compare_directories(c));
    compared.back().geometry.name = study.cases[k].label;
    CalibrationRow row;
    row.case_name = study.cases[k].name;
    for (std::size_t i = 0; i < result.keys.size(); ++i) row.values.push_back(result.keys[i].values[grid[k][i]]);
    row.error = error_of_case[k] = compared.back().error.rms_normalised();
    row.bias = compared.back().error.bias_normalised();
    row.coverage = compared.back().error.coverage;
    row.run_dir = c.dem_dir;
    result.ranked.push_back(std::move(row));
  }
  std::stable_sort(result.ranked.begin(), result.ranked.end(),
                   [](const CalibrationRow& a, const CalibrationRow& b) { return a.error < b.error; });

  write_text_atomically(result.out / "calibration.csv", rows_csv(result));
  const CalibrationRow& best = result.ranked.front();
  std::string header = fmt::format("# trapdem calibrate: the best of {} cases against {} at {} (RMS(w_DEM - w_PIV)/delta "
                                   "= {:.3f} %):", study.cases.size(), o.target, o.at, 100.0 * best.error);
  for (std::size_t i = 0; i < result.keys.size(); ++i) header += fmt::format(" {} = {}", result.keys[i].key, best.values[i]);
  write_text_atomically(result.out / "best.toml", header + "\n" + read_text_file(RunFolder(best.run_dir).resolved_toml()));
  plot::write_error_surface(plot::with_format(result.out / "error_surface", format),
                            error_surface(result, grid, error_of_case, o.at));
  for (std::size_t k = 0; k < study.cases.size(); ++k)
    if (study.cases[k].name == best.case_name)
      write_compare_figure(compared[k], plot::with_format(result.out / "compare_best", format));
  write_study_outputs(study, scale, result.out, true, {}, format);
  return result;
}
}  // namespace trapdem
