#include "study/study_runner.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
#include "study/sinkhole_run.hpp"
#include "core/errors.hpp"
#include "core/json.hpp"
#include "core/length_text.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/ground_reaction.hpp"
#include "experiment/presets.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_identity.hpp"
#include "experiment/run_record.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"
#include "study/case_element_test.hpp"
#include "study/parameter_differences.hpp"
#include "study/run_analysis.hpp"
#include "study/stored_analysis.hpp"
#include "study/study_report.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

fs::path base_file(const ConfigRecipe& recipe, const fs::path& presets) {
  return recipe.config.empty() ? preset_file(presets, recipe.preset) : recipe.config;
}

fs::path study_record(const fs::path& out) { return out / "study.json"; }

// How the configuration of a run folder differs from the case's now ("" where it does not): its
// resolved.toml read again by this trapdem, as a resume reads it, and compared key by key. So a key
// added to trapdem since the run, which comes in at its default (a new key's default keeps the old
// behaviour), and the description (text for people) do not cost a study its finished runs; a value
// that differs, or a key this trapdem no longer reads, does.
std::string configuration_change(const RunFolder& run, const std::string& resolved_now) {
  if (!fs::exists(run.resolved_toml())) return "it has no resolved.toml";
  std::string there;
  try {
    there = as_read_now(read_text_file(run.resolved_toml()), run.resolved_toml().string().c_str());
  } catch (const InputError& e) {
    return fmt::format("its resolved.toml does not read as a configuration of this trapdem: {}", e.what());
  }
  for (const ConfigChange& c : config_changes(there, resolved_now))
    if (c.key != "description") return fmt::format("{} is {} there, {} now", c.key, c.before, c.after);
  return "";
}

// The configuration a recipe resolves to (resolved.toml's text), checked as `trapdem run` checks it;
// its packing seed into *seed if asked. Errors name the case.
std::string resolved_recipe(const ConfigRecipe& recipe, const fs::path& presets, const std::string& case_name,
                            std::uint64_t* seed) {
  try {
    Config config = Config::load_file(base_file(recipe, presets).string());
    config.apply_overrides(recipe.overrides);
    const ExperimentConfig experiment = ExperimentConfig::from(config);
    if (seed) *seed = experiment.pluviation.seed;
    return config.resolved_toml();
  } catch (const InputError& e) {
    throw InputError(fmt::format("case '{}': {}", case_name, e.what()));
  }
}

}  // namespace

std::string run_title(const StudyCase& study_case, const CaseRun& run) {
  return run.replicate ? fmt::format("{} seed {}", study_case.name, run.seed) : study_case.name;
}

void log_study_line(const fs::path& out, const std::string& line, bool quiet, const LineSink& terminal) {
  if (!quiet) terminal.say(line);
  std::ofstream log(out / "study.log", std::ios::app);
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  log << stamp << "  " << line << '\n';
}

std::string resolved_case_configuration(const StudyCase& c, const StudyScale& scale, const fs::path& presets) {
  return resolved_recipe(case_recipe(c, scale), presets, c.name, nullptr);
}

fs::path case_directory(const fs::path& out, const StudyCase& study_case) { return out / "cases" / study_case.name; }

fs::path element_directory(const fs::path& out, const StudyCase& study_case) {
  return case_directory(out, study_case) / "element";
}

std::vector<CaseRun> case_runs(const StudyDefinition& study, const StudyCase& c, const StudyScale& scale,
                               const fs::path& out, const fs::path& presets) {
  const ConfigRecipe recipe = case_recipe(c, scale);
  const ReplicateRequest& request = case_replicates(study, c, scale);
  std::uint64_t case_seed = 0;
  const std::string own_seed_resolved = resolved_recipe(recipe, presets, c.name, &case_seed);
  std::vector<CaseRun> runs;
  for (std::uint64_t seed : replicate_seeds(request, case_seed)) {
    CaseRun run;
    run.seed = seed;
    run.replicate = request.asked();
    run.recipe = recipe;
    run.dir = case_directory(out, c);
    if (run.replicate) {
      run.dir /= replicate_folder_name(seed);
      run.recipe.overrides.push_back(fmt::format("pluviation.seed={}", seed));
      run.resolved = resolved_recipe(run.recipe, presets, c.name, nullptr);
    } else {
      run.resolved = own_seed_resolved;
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

bool holds_study(const fs::path& out) { return fs::exists(study_record(out)); }

void claim_study_folder(const StudyDefinition& study, const StudyScale& scale, const fs::path& out) {
  const fs::path record = study_record(out);
  if (fs::exists(record)) {
    const Json j = Json::parse(read_text_file(record), record.string());
    const std::string name = j["study"].as_string(), was = j["scale"].as_string();
    if (name != study.name || was != scale.name)
      throw InputError(fmt::format("{} holds study '{}' at scale '{}', not '{}' at '{}': choose another --out",
                                   out.string(), name, was, study.name, scale.name));
    return;
  }
  Json j = Json::object();
  j.set("study", study.name);
  j.set("scale", scale.name);
  // Relative to the study folder, so that a published copy names no machine's absolute path.
  j.set("study_file", study.source.empty() ? "" : fs::relative(fs::absolute(study.source), fs::absolute(out)).generic_string());
  Json cases = Json::array();
  for (const StudyCase& c : study.cases) cases.push_back(c.name);
  j.set("cases", cases);
  write_text_atomically(record, j.dump() + "\n");
}

fs::path case_base_file(const CaseRun& run, const fs::path& preset_directory) {
  return base_file(run.recipe, preset_directory);
}

std::vector<std::vector<CaseRun>> checked_study_runs(const StudyDefinition& study, const StudyScale& scale,
                                                     const fs::path& out, const fs::path& preset_directory) {
  std::vector<std::vector<CaseRun>> runs;
  for (const StudyCase& c : study.cases) {
    runs.push_back(case_runs(study, c, scale, out, preset_directory));
    for (const CaseRun& r : runs.back()) {
      const RunFolder run(r.dir);
      if (!run.has_checkpoint() && !run_finished(run)) continue;
      const std::string change = configuration_change(run, r.resolved);
      if (!change.empty())
        throw InputError(fmt::format("{}: holds a run of another configuration than case '{}' now has ({}); remove "
                                     "the folder to run the case again, or choose another --out",
                                     r.dir.string(), c.name, change));
    }
    if (study.report.element_test) {  // its keys checked now too
      const ConfigRecipe recipe = case_recipe(c, scale);
      case_element_test(c, base_file(recipe, preset_directory), recipe, study.report);
    }
  }
  return runs;
}

bool run_study_cases(const StudyDefinition& study, const StudyScale& scale, const fs::path& out,
                     const StudyRunSettings& settings) {
  const bool quiet = settings.quiet;
  // Every run's configuration first, and each against what its folder holds: a typo in the fourth
  // case, or a case changed since it ran, should not wait for three runs.
  const std::vector<std::vector<CaseRun>> runs = checked_study_runs(study, scale, out, settings.preset_directory);
  check_run_selection(settings.only, study, runs);
  std::size_t total = 0, all = 0;
  for (std::size_t k = 0; k < study.cases.size(); ++k)
    for (const CaseRun& r : runs[k]) {
      ++all;
      if (settings.only.selects(study.cases[k].name, r.seed)) ++total;
    }
  if (!settings.only.everything())
    log_study_line(out, fmt::format("{} of the study's {} runs selected ({})", total, all, settings.only.describe()),
                   quiet, settings.terminal);

  std::size_t counted = 0;
  // The budget's clock starts with the first run that starts or resumes (so that a tiny budget still
  // runs one step and writes its checkpoint: what the same call again resumes).
  std::optional<std::chrono::steady_clock::time_point> first_run_started;
  for (std::size_t k = 0; k < study.cases.size(); ++k) {
    const StudyCase& c = study.cases[k];
    bool case_selected = false;
    for (const CaseRun& r : runs[k]) {
      if (!settings.only.selects(c.name, r.seed)) continue;
      case_selected = true;
      const RunFolder folder(r.dir);
      const fs::path& dir = folder.path();
      const std::string counter = fmt::format("[{}/{}] {}", ++counted, total, run_title(c, r));
      const bool has_checkpoint = folder.has_checkpoint();
      FolderRunOptions run;
      run.threads = settings.threads;
      run.quiet = quiet;
      run.terminal = settings.terminal;
      if (run_finished(folder)) {
        log_study_line(out, fmt::format("{}: finished before, skipped", counter), quiet, settings.terminal);
        continue;
      }
      if (settings.stop_after_seconds > 0.0) {
        const auto now = std::chrono::steady_clock::now();
        if (!first_run_started) first_run_started = now;
        const double left = settings.stop_after_seconds - std::chrono::duration<double>(now - *first_run_started).count();
        if (left <= 0.0) {
          log_study_line(out, fmt::format("{}: not started: the study's time budget of {:g} s (--stop-after) is "
                                          "spent; run the same command again to carry on", counter, settings.stop_after_seconds),
                         quiet, settings.terminal);
          return false;
        }
        run.stop_after_seconds = left;
      }
      if (has_checkpoint) {
        log_study_line(out, fmt::format("{}: resuming from its checkpoint", counter), quiet, settings.terminal);
        run.resume_dir = dir;
      } else {
        // Killed before its first checkpoint: nothing to keep.
        if (fs::exists(dir)) fs::remove_all(dir);
        log_study_line(out, fmt::format("{}: running ({})", counter, c.label), quiet, settings.terminal);
        run.config_file = base_file(r.recipe, settings.preset_directory);
        run.overrides = r.recipe.overrides;
        run.out_dir = dir;
      }
      if (!run_in_folder(run)) {
        log_study_line(out, fmt::format("{}: {} (checkpoint written); run the same command again to carry on", counter,
                                        run.stop_after_seconds > 0.0 ? "stopped (a signal, or the study's time budget)" : "interrupted"),
                       quiet, settings.terminal);
        return false;
      }
      log_study_line(out, fmt::format("{}: finished", counter), quiet, settings.terminal);
    }
    if (study.report.element_test && case_selected) run_case_element_test_once(study, c, scale, out, settings);
  }
  return true;
}

void run_case_element_test_once(const StudyDefinition& study, const StudyCase& c, const StudyScale& scale,
                                const fs::path& out, const StudyRunSettings& settings) {
  const ConfigRecipe recipe = case_recipe(c, scale);
  const CaseElementTest test = case_element_test(c, base_file(recipe, settings.preset_directory), recipe, study.report);
  const std::string title = fmt::format("{} element test", c.name);
  const fs::path dir = element_directory(out, c);
  if (element_test_finished(test, dir)) {
    log_study_line(out, fmt::format("{}: finished before, skipped", title), settings.quiet, settings.terminal);
  } else {
    log_study_line(out, fmt::format("{}: running ({} particles)", title, test.setup.settings.particles), settings.quiet, settings.terminal);
    run_case_element_test(test, dir, settings.threads);
    log_study_line(out, fmt::format("{}: finished", title), settings.quiet, settings.terminal);
  }
}

namespace {

// The numbers of a run that do not come from its analysis: the ground reaction curve and the
// sinkhole estimate (from analysis/metrics.json, see sinkhole_run.hpp).
void read_run_numbers(const StudyCase& c, const CaseRun& run, const StudyReportSettings& report, bool quiet,
                      const LineSink& terminal, CaseSummary& summary) {
  const RunFolder folder(run.dir);
  const fs::path csv = folder.trapdoor_csv();
  if (fs::exists(csv))
    read_ground_reaction(parse_ground_reaction_csv(read_text_file(csv), csv.string()), summary.trapdoor_width, summary);
  try {
    read_sinkhole_comparison(compare_with_dem(read_dem_run(run.dir), report.angle_of_draw_deg), summary);
  } catch (const InputError& e) {
    if (!quiet) terminal.say(fmt::format("{}: no sinkhole estimate: {}", run_title(c, run), e.what()));
  }
}

// One finished run analysed (its analysis/ written) and summarised; the analyses are kept in
// `finals` and `contours` for the report's figures. A run that cannot be analysed (too few
// particles in view, say) gets a note and does not hide the others. A finished run whose
// snapshots are gone is summarised from the analysis it kept (stored_analysis.hpp), without figures.
StudyRunResult summarise_run(const StudyDefinition& study, const StudyCase& c, const CaseRun& run,
                             const fs::path& out, bool quiet, const LineSink& terminal, plot::FigureFormat format,
                             std::vector<std::unique_ptr<AnalysisResult>>& finals,
                             std::vector<std::unique_ptr<AnalysisResult>>& contours) {
  const RunFolder folder(run.dir);
  StudyRunResult r;
  r.run_dir = run.dir;
  r.summary.name = c.name;
  r.summary.label = c.label;
  r.summary.replicate = run.replicate;
  r.summary.seed = run.replicate ? run.seed : 0;
  if (!run_finished(folder)) {
    r.missing_note = "the run has not finished";
    return r;
  }
  r.summary.cost = read_case_cost(run.dir);
  if (!folder.has_snapshots()) {
    const StoredAnalysis stored = stored_final_analysis(folder, out);
    r.missing_note = stored.note;
    if (!stored.metrics) return r;
    r.stored_strain_figure = stored.strain_figure;
    r.stored_displacement_figure = stored.displacement_figure;
    if (stored.strain_map) {
      auto map = std::make_shared<plot::StoredStrainMap>(std::move(*stored.strain_map));
      map->name = c.label;
      r.stored_strain_map = std::move(map);
    } else {
      r.missing_note += fmt::format("; not in the strain panel: {}", stored.strain_map_note);
    }
    read_mechanism_metrics(*stored.metrics, r.summary);
    read_run_numbers(c, run, study.report, quiet, terminal, r.summary);
    r.analysed = true;
    return r;
  }
  AnalyzeOptions a;
  a.dir = run.dir.string();
  a.quiet = true;
  a.format = plot::extension_of(format).substr(1);
  try {
    finals.push_back(std::make_unique<AnalysisResult>(analyze_and_write(a)));
  } catch (const InputError& e) {
    r.missing_note = fmt::format("not analysed: {}", e.what());
    return r;
  }
  AnalysisResult& final_analysis = *finals.back();
  final_analysis.geometry.name = c.label;
  r.final_analysis = &final_analysis;
  read_mechanism_metrics(metrics_json(final_analysis), r.summary);

  AnalyzeOptions at = a;
  at.at = fmt::format("{}m", study.report.contours_at);
  try {
    contours.push_back(std::make_unique<AnalysisResult>(analyze_directory(at)));
    contours.back()->geometry.name = c.label;
    r.contour_analysis = contours.back().get();
  } catch (const InputError& e) {
    r.missing_note = fmt::format("no contours at {}: {}", format_mm(study.report.contours_at), e.what());
  }
  read_run_numbers(c, run, study.report, quiet, terminal, r.summary);
  r.analysed = true;
  return r;
}

}  // namespace

fs::path write_study_outputs(const StudyDefinition& study, const StudyScale& scale, const fs::path& out, bool quiet,
                             const fs::path& preset_directory, plot::FigureFormat format, const LineSink& terminal) {
  StudyReportInput input;
  input.study_name = study.name;
  input.description = study.description;
  input.scale = scale.name;
  input.scale_description = scale.description;
  input.settings = study.report;
  input.format = format;
  // Results live here so that the report can point at them.
  std::vector<std::unique_ptr<AnalysisResult>> finals, contours;
  for (const StudyCase& c : study.cases) {
    StudyCaseResult r;
    r.run_dir = case_directory(out, c);
    std::vector<CaseSummary> analysed;
    for (const CaseRun& run : case_runs(study, c, scale, out, preset_directory)) {
      r.runs.push_back(summarise_run(study, c, run, out, quiet, terminal, format, finals, contours));
      const StudyRunResult& last = r.runs.back();
      if (!last.analysed) continue;
      analysed.push_back(last.summary);
      if (!r.final_analysis) {  // the figures show the first analysed run that has them
        r.final_analysis = last.final_analysis;
        r.contour_analysis = last.contour_analysis;
        r.figure_run = last.run_dir;
        r.parameters = resolved_parameters(last.run_dir);
        r.missing_note = last.contour_analysis ? "" : last.missing_note;
      }
      if (!r.final_analysis && r.stored_strain_figure.empty() && r.stored_displacement_figure.empty()) {
        r.stored_strain_figure = last.stored_strain_figure;
        r.stored_displacement_figure = last.stored_displacement_figure;
      }
      if (!r.final_analysis && !r.stored_strain_map) r.stored_strain_map = last.stored_strain_map;
    }
    if (r.final_analysis) {
      r.stored_strain_figure = r.stored_displacement_figure = fs::path();
      r.stored_strain_map.reset();
    }
    if (analysed.empty()) {
      r.summary.name = c.name;
      r.summary.label = c.label;
      for (const StudyRunResult& run : r.runs)
        if (!run.missing_note.empty()) r.missing_note = run.missing_note;
      if (r.missing_note.empty()) r.missing_note = "no run";
    }
    r.ensemble = make_ensemble(std::move(analysed));
    if (r.ensemble.replicates.empty())
      r.ensemble.mean = r.summary;
    else
      r.summary = r.ensemble.mean;
    if (study.report.element_test) {
      const CaseElementAngles angles = read_case_element_angles(element_directory(out, c));
      r.summary.phi_peak_deg = angles.phi_peak_deg;
      r.summary.phi_cs_deg = angles.phi_cs_deg;
      r.ensemble.mean.phi_peak_deg = angles.phi_peak_deg;
      r.ensemble.mean.phi_cs_deg = angles.phi_cs_deg;
      r.element_confining = angles.confining;
    }
    input.cases.push_back(std::move(r));
  }
  return write_study_report(out / "report", input);
}

bool run_study_in_folder(const StudyDefinition& study, const StudyScale& scale, const fs::path& out,
                         const StudyRunSettings& settings) {
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw FileError(fmt::format("cannot create the study folder {}: {}", out.string(), ec.message()));
  claim_study_folder(study, scale, out);
  log_study_line(out, fmt::format("study '{}' at scale '{}' ({} cases) in {}", study.name, scale.name,
                                  study.cases.size(), out.string()), settings.quiet, settings.terminal);
  return run_study_cases(study, scale, out, settings);
}

}  // namespace trapdem
