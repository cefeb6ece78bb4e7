#pragma once
// `trapdem study STUDY.toml [--out DIR] [--scale NAME]`: the study runner of study/study_runner.hpp
// on the command line (docs/study.md).
#include <string>

namespace trapdem::app {

struct StudyOptions {
  std::string file;           // the study file
  std::string out;            // empty: trapdem-out/<study name>-<scale>
  std::string scale;          // empty: the study's default_scale
  int threads = 0;            // OpenMP threads per run; 0: each configuration's numerics.threads, else all
  bool quiet = false;         // the runs' progress lines only in their run.log
  bool report_only = false;   // no running: report on the cases that finished
};

// The whole command. Returns the exit code (130 if interrupted).
int run_study(const StudyOptions& options);

}  // namespace trapdem::app
