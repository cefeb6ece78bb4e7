#pragma once
// Runs a study's cases one after another, each in DIR/cases/<name>/ (experiment/folder_run.hpp),
// then analyses them and writes DIR/report/index.html (docs/study.md). Started again on the same
// folder it skips finished cases and resumes an unfinished one from its checkpoint, so an
// interrupted study loses at most the work since the last checkpoint.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/line_sink.hpp"
#include "plot/figure_format.hpp"
#include "study/run_selection.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

struct StudyRunSettings {
  std::filesystem::path preset_directory;  // where the recipes' preset names are found
  int threads = 0;                         // OpenMP threads per run; 0: each configuration's numerics.threads
  bool quiet = false;                      // the runs' progress lines only in their run.log
  LineSink terminal;                       // where the study's and its runs' lines go (default: stdout, stderr)
  // > 0: the study's wall-clock budget (s), counted from its first run's start: the run going when it
  // is spent stops with its checkpoint, and no run starts after it (a shared host's working hours, a
  // batch job's time limit); the same call again carries on.
  double stop_after_seconds = 0.0;
  // The runs this call runs (the others are left as they are); every run by default.
  RunSelection only{};
};

// The case's configuration at the scale as `trapdem run` resolves it (resolved.toml's text); throws
// InputError naming the case if it does not validate.
std::string resolved_case_configuration(const StudyCase& study_case, const StudyScale& scale,
                                        const std::filesystem::path& preset_directory);

std::filesystem::path case_directory(const std::filesystem::path& out, const StudyCase& study_case);

// One run of a case: its only run (no replicates asked: cases/<name>/, the configuration's own seed)
// or one of its replicates (cases/<name>/seed-<seed>/, pluviation.seed = seed; study/replicates.hpp).
struct CaseRun {
  std::uint64_t seed = 0;              // the packing seed (pluviation.seed) it runs with
  bool replicate = false;
  std::filesystem::path dir;
  ConfigRecipe recipe;                 // case_recipe, then pluviation.seed for a replicate
  std::string resolved;                // the recipe's resolved configuration (TOML), read and checked once
};
// The run's name in logs and job titles: the case's, with its packing seed for a replicate.
std::string run_title(const StudyCase& study_case, const CaseRun& run);

// The case's runs in seed order, each with its configuration resolved once (the case's own seed's
// serves a case without replicates). Throws InputError naming the case if its configuration does
// not validate.
std::vector<CaseRun> case_runs(const StudyDefinition& study, const StudyCase& study_case, const StudyScale& scale,
                               const std::filesystem::path& out, const std::filesystem::path& preset_directory);

// The case's element test (report.element_test): its folder, cases/<name>/element/.
std::filesystem::path element_directory(const std::filesystem::path& out, const StudyCase& study_case);

// Every case's runs (case_runs), each configuration resolved and checked, each against what its
// folder holds (InputError for a folder holding a run of another configuration), and the element
// test's keys (report.element_test): what a study checks before its first run, whether it runs
// the cases here or submits them (study/slurm_submission.hpp).
std::vector<std::vector<CaseRun>> checked_study_runs(const StudyDefinition& study, const StudyScale& scale,
                                                     const std::filesystem::path& out,
                                                     const std::filesystem::path& preset_directory);

// The configuration file a run starts from (its preset's file, or its configuration file).
std::filesystem::path case_base_file(const CaseRun& run, const std::filesystem::path& preset_directory);

// The case's element test (report.element_test) into element_directory, unless a finished test of
// the same configuration is there; logged in study.log.
void run_case_element_test_once(const StudyDefinition& study, const StudyCase& study_case, const StudyScale& scale,
                                const std::filesystem::path& out, const StudyRunSettings& settings);

// Runs (or resumes, or skips) every case of `study` at `scale` into out/cases/<name> (the runs of
// settings.only: InputError for a case or seed it does not have, check_run_selection). Returns false
// if a run was interrupted (SIGINT/SIGTERM or the settings' stop_after_seconds: its checkpoint is
// written) or the budget was spent before a run started. Throws InputError if a case's folder holds
// a run of another configuration.
bool run_study_cases(const StudyDefinition& study, const StudyScale& scale, const std::filesystem::path& out,
                     const StudyRunSettings& settings);

// The study's identity in its folder (out/study.json): written the first time, and another study or
// scale in the same folder refused (InputError).
void claim_study_folder(const StudyDefinition& study, const StudyScale& scale, const std::filesystem::path& out);
bool holds_study(const std::filesystem::path& out);

// Creates `out`, claims it for this study and scale (refusing another's), then run_study_cases.
bool run_study_in_folder(const StudyDefinition& study, const StudyScale& scale, const std::filesystem::path& out,
                         const StudyRunSettings& settings);

// Analyses every finished run and writes out/report/, the runs' analysis figures and the report's
// in `format`. Returns the page's path. Its notes (a run without a sinkhole estimate) go to
// `terminal` unless quiet.
std::filesystem::path write_study_outputs(const StudyDefinition& study, const StudyScale& scale,
                                          const std::filesystem::path& out, bool quiet,
                                          const std::filesystem::path& preset_directory = {},
                                          plot::FigureFormat format = plot::FigureFormat::png,
                                          const LineSink& terminal = {});

// Appends a line to out/study.log (time-stamped) and says it on `terminal` unless quiet.
void log_study_line(const std::filesystem::path& out, const std::string& line, bool quiet,
                    const LineSink& terminal = {});

}  // namespace trapdem
