#include "study_command.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "analysis/analysis_output.hpp"
#include "core/length_text.hpp"
#include "core/json.hpp"
#include "analysis/sinkhole.hpp"
#include "analyze_command.hpp"
#include "core/errors.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/ground_reaction.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"
#include "run_command.hpp"
#include "study/parameter_differences.hpp"
#include "study/study_report.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

namespace {

// Appends a line to DIR/study.log and prints it (unless quiet).
void say(const fs::path& out, const std::string& line, bool quiet) {
  if (!quiet) {
    fmt::print("{}\n", line);
    std::fflush(stdout);
  }
  std::ofstream log(out / "study.log", std::ios::app);
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  log << stamp << "  " << line << '\n';
}

fs::path base_file(const ConfigRecipe& recipe) {
  return recipe.config.empty() ? preset_path(recipe.preset) : recipe.config;
}

}  // namespace

std::string resolved_case_configuration(const StudyCase& c, const StudyScale& scale) {
  const ConfigRecipe recipe = case_recipe(c, scale);
  try {
    Config config = Config::load_file(base_file(recipe).string());
    config.apply_overrides(recipe.overrides);
    ExperimentConfig::from(config);
    return config.resolved_toml();
  } catch (const InputError& e) {
    throw InputError(fmt::format("case '{}': {}", c.name, e.what()));
  }
}

namespace {

// The first line where two resolved configurations differ, for the message.
std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t line = 1, pos_a = 0, pos_b = 0;
  while (pos_a < a.size() || pos_b < b.size()) {
    const std::size_t end_a = std::min(a.find('\n', pos_a), a.size()), end_b = std::min(b.find('\n', pos_b), b.size());
    const std::string la = a.substr(pos_a, end_a - pos_a), lb = b.substr(pos_b, end_b - pos_b);
    if (la != lb) return fmt::format("line {}: '{}' there, '{}' now", line, la, lb);
    pos_a = end_a + 1;
    pos_b = end_b + 1;
    ++line;
  }
  return "";
}

bool run_finished(const fs::path& dir) {
  const fs::path record = dir / "run.json";
  if (!fs::exists(record)) return false;
  try {
    const Json j = Json::parse(read_text_file(record), record.string());
    return j.contains("complete") && j["complete"].as_bool();
  } catch (const InputError&) {
    return false;  // an unreadable record: resume, which finishes at once if the run had
  }
}

// The study's identity in its folder: another study or scale in the same folder is refused.
void claim_folder(const StudyDefinition& study, const StudyScale& scale, const fs::path& out) {
  const fs::path record = out / "study.json";
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
  j.set("study_file", study.source.empty() ? "" : fs::absolute(study.source).string());
  Json cases = Json::array();
  for (const StudyCase& c : study.cases) cases.push_back(c.name);
  j.set("cases", cases);
  write_text_atomically(record, j.dump() + "\n");
}

}  // namespace

fs::path case_directory(const fs::path& out, const StudyCase& study_case) { return out / "cases" / study_case.name; }

bool run_study_cases(const StudyDefinition& study, const StudyScale& scale, const fs::path& out, int threads,
                     bool quiet) {
  // Every case's configuration first, and each against what its folder holds: a typo in the fourth
  // case, or a case changed since it ran, should not wait for three runs.
  for (const StudyCase& c : study.cases) {
    const std::string resolved = resolved_case_configuration(c, scale);
    const fs::path dir = case_directory(out, c);
    if (!fs::exists(dir / "checkpoint.h5") && !run_finished(dir)) continue;
    const std::string there = fs::exists(dir / "resolved.toml") ? read_text_file(dir / "resolved.toml") : "";
    if (there != resolved)
      throw InputError(fmt::format("{}: holds a run of another configuration than case '{}' now has ({}); remove "
                                   "the folder to run the case again, or choose another --out",
                                   dir.string(), c.name, first_difference(there, resolved)));
  }

  for (std::size_t k = 0; k < study.cases.size(); ++k) {
    const StudyCase& c = study.cases[k];
    const fs::path dir = case_directory(out, c);
    const std::string counter = fmt::format("[{}/{}] {}", k + 1, study.cases.size(), c.name);
    const bool has_checkpoint = fs::exists(dir / "checkpoint.h5");
    RunOptions run;
    run.threads = threads;
    run.quiet = quiet;
    if (run_finished(dir)) {
      say(out, fmt::format("{}: finished before, skipped", counter), quiet);
      continue;
    }
    if (has_checkpoint) {
      say(out, fmt::format("{}: resuming from its checkpoint", counter), quiet);
      run.resume_dir = dir.string();
    } else {
      // Killed before its first checkpoint: nothing to keep.
      if (fs::exists(dir)) fs::remove_all(dir);
      const ConfigRecipe recipe = case_recipe(c, scale);
      say(out, fmt::format("{}: running ({})", counter, c.label), quiet);
      run.config_file = base_file(recipe).string();
      run.overrides = recipe.overrides;
      run.out_dir = dir.string();
    }
    const int code = run_experiment(run);
    if (code != 0) {
      say(out, fmt::format("{}: interrupted (checkpoint written); run the same command again to carry on", counter), quiet);
      return false;
    }
    say(out, fmt::format("{}: finished", counter), quiet);
  }
  return true;
}

fs::path write_study_outputs(const StudyDefinition& study, const StudyScale& scale, const fs::path& out, bool quiet) {
  StudyReportInput input;
  input.study_name = study.name;
  input.description = study.description;
  input.scale = scale.name;
  input.scale_description = scale.description;
  input.settings = study.report;
  // Results live here so that the report can point at them.
  std::vector<std::unique_ptr<AnalysisResult>> finals, contours;
  for (const StudyCase& c : study.cases) {
    const fs::path dir = case_directory(out, c);
    StudyCaseResult r;
    r.run_dir = dir;
    r.summary.name = c.name;
    r.summary.label = c.label;
    if (!run_finished(dir)) {
      r.missing_note = "the run has not finished";
      input.cases.push_back(std::move(r));
      continue;
    }
    AnalyzeOptions a;
    a.dir = dir.string();
    a.quiet = true;
    try {
      finals.push_back(std::make_unique<AnalysisResult>(analyze_and_write(a)));
    } catch (const InputError& e) {
      // One case that cannot be analysed (too few particles in view, say) does not hide the others.
      r.missing_note = fmt::format("not analysed: {}", e.what());
      r.summary.cost = read_case_cost(dir);
      input.cases.push_back(std::move(r));
      continue;
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
    const fs::path csv = dir / "trapdoor.csv";
    if (fs::exists(csv))
      read_ground_reaction(parse_ground_reaction_csv(read_text_file(csv), csv.string()), r.summary.trapdoor_width,
                           r.summary);
    r.summary.cost = read_case_cost(dir);
    try {
      read_sinkhole_comparison(compare_with_dem(read_dem_run(dir), study.report.angle_of_draw_deg), r.summary);
    } catch (const InputError& e) {
      if (!quiet) fmt::print("{}: no sinkhole estimate: {}\n", c.name, e.what());
    }
    r.parameters = resolved_parameters(dir);
    input.cases.push_back(std::move(r));
  }
  return write_study_report(out / "report", input);
}

bool run_study_in_folder(const StudyDefinition& study, const StudyScale& scale, const fs::path& out, int threads,
                         bool quiet) {
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw FileError(fmt::format("cannot create the study folder {}: {}", out.string(), ec.message()));
  claim_folder(study, scale, out);
  say(out, fmt::format("study '{}' at scale '{}' ({} cases) in {}", study.name, scale.name, study.cases.size(),
                       out.string()), quiet);
  return run_study_cases(study, scale, out, threads, quiet);
}

int run_study(const StudyOptions& o) {
  const StudyDefinition study = load_study(o.file);
  const StudyScale& scale = study.scale(o.scale.empty() ? study.default_scale : o.scale);
  const fs::path out = o.out.empty() ? fs::path("trapdem-out") / (study.name + "-" + scale.name) : fs::path(o.out);
  if (o.report_only) {
    if (!fs::exists(out / "study.json")) throw InputError(fmt::format("--report-only: {} holds no study", out.string()));
    claim_folder(study, scale, out);
  } else if (!run_study_in_folder(study, scale, out, o.threads, o.quiet)) {
    return 130;
  }
  const fs::path page = write_study_outputs(study, scale, out, o.quiet);
  say(out, fmt::format("report: {}", page.string()), o.quiet);
  if (!o.quiet) {
    const Json summary = Json::parse(read_text_file(out / "report" / "summary.json"));
    for (std::size_t k = 0; k < summary["findings"].size(); ++k)
      fmt::print("  - {}\n", summary["findings"][k].as_string());
  }
  return 0;
}

}  // namespace trapdem::app
