#pragma once
// `trapdem study STUDY.toml [--out DIR] [--scale NAME]`: runs a study's cases one after another, each
// in DIR/cases/<name>/, then analyses them and writes DIR/report/index.html (docs/study.md).
// Started again on the same folder it skips finished cases and resumes an unfinished one from its
// checkpoint, so an interrupted study loses at most the work since the last checkpoint.
#include <filesystem>
#include <string>

#include "study/study_definition.hpp"

namespace trapdem::app {

struct StudyOptions {
  std::string file;           // the study file
  std::string out;            // empty: trapdem-out/<study name>-<scale>
  std::string scale;          // empty: the study's default_scale
  int threads = 0;            // OpenMP threads per run; 0: each configuration's numerics.threads, else all
  bool quiet = false;         // the runs' progress lines only in their run.log
  bool report_only = false;   // no running: report on the cases that finished
};

// What happened to each case in this invocation.
enum class CaseAction { ran, resumed, skipped_finished };

// Runs (or resumes, or skips) every case of `study` at `scale` into out/cases/<name>. Returns false
// if a run was interrupted (SIGINT/SIGTERM: its checkpoint is written). Throws InputError if a case's
// folder holds a run of another configuration.
bool run_study_cases(const StudyDefinition& study, const StudyScale& scale, const std::filesystem::path& out,
                     int threads, bool quiet);

// Creates `out`, claims it for this study and scale (refusing another's), then run_study_cases.
bool run_study_in_folder(const StudyDefinition& study, const StudyScale& scale, const std::filesystem::path& out,
                         int threads, bool quiet);

// Analyses every finished case and writes out/report/. Returns the page's path.
std::filesystem::path write_study_outputs(const StudyDefinition& study, const StudyScale& scale,
                                          const std::filesystem::path& out, bool quiet);

// The case's configuration at the scale as `trapdem run` resolves it (resolved.toml's text); throws
// InputError naming the case if it does not validate.
std::string resolved_case_configuration(const StudyCase& study_case, const StudyScale& scale);

std::filesystem::path case_directory(const std::filesystem::path& out, const StudyCase& study_case);

// The whole command. Returns the exit code (130 if interrupted).
int run_study(const StudyOptions& options);

}  // namespace trapdem::app
