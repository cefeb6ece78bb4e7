#pragma once
// `trapdem study STUDY.toml [--out DIR] [--scale NAME]`: the study runner of study/study_runner.hpp
// on the command line (docs/study.md); with `--submit slurm` its runs go to a Slurm cluster
// (study/slurm_submission.hpp), `--status` says where each run stands (study/study_status.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "study/slurm_options.hpp"

namespace trapdem::app {

// --submit and the Slurm options, shared by `study` and `calibrate`.
struct SubmitOptions {
  std::string submit;         // "slurm", or empty: run here
  SlurmOptions slurm;
};

struct StudyOptions {
  std::string file;           // the study file
  std::string out;            // empty: trapdem-out/<study name>-<scale>
  std::string scale;          // empty: the study's default_scale
  int threads = 0;            // OpenMP threads per run; 0: each configuration's numerics.threads, else all
  bool quiet = false;         // the runs' progress lines only in their run.log
  bool report_only = false;   // no running: report on the cases that finished
  bool collect = false;       // no trapdoor run: the element tests still missing, then the report (Slurm's report job)
  bool status = false;        // no running: where each run stands
  std::string format = "png"; // the report's and the runs' analysis figures: png | svg | pdf
  double stop_after_seconds = 0.0;  // > 0: the study's wall-clock budget (StudyRunSettings)
  std::vector<std::string> cases;       // --case: only these cases' runs (StudyRunSettings::only)
  std::vector<std::uint64_t> seeds;     // --seed: only the runs with these packing seeds
  SubmitOptions submit;
};

// The whole command. Returns the exit code (130 if interrupted).
int run_study(const StudyOptions& options);

// The trapdem program running now (for the job scripts), absolute.
std::filesystem::path this_program();

// The lines printed after a submission: job ids and the commands to watch.
void print_submission(const std::string& what, const std::filesystem::path& array_script, const std::string& array_job,
                      const std::string& report_job, std::size_t submitted, std::size_t runs,
                      const std::string& status_command);

}  // namespace trapdem::app
