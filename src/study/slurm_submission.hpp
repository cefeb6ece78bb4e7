#pragma once
// A study submitted to Slurm (`trapdem study STUDY.toml --submit slurm`, issue 16): every case
// resolved and checked as for a local study, the study folder written, then one job array with a
// task per run not yet finished (its script lists every run; a task starts, resumes or skips its
// run by what the run's folder holds) and one report job that depends on the array
// (--dependency=afterany) and writes the report. Both scripts stay in DIR/slurm/. Slurm is asked
// through its commands (sinfo, sbatch --parsable, scancel), run as processes.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "study/slurm_options.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

struct SlurmStudyJobs {
  std::filesystem::path trapdem;                // the trapdem program the jobs run (absolute)
  std::vector<std::string> report_arguments;    // trapdem's arguments for the report job
  std::vector<std::string> comment;             // for the scripts' heads (how to submit them again)
};

struct SlurmSubmission {
  std::filesystem::path array_script;           // DIR/slurm/array.sbatch
  std::filesystem::path report_script;          // DIR/slurm/report.sbatch
  std::string array_job;                        // its job id; empty when every run had finished
  std::string report_job;
  std::size_t runs = 0;                         // runs in the study
  std::vector<std::string> submitted;           // the titles of the runs submitted (not finished)
};

// The job id `sbatch --parsable` printed ("1234" or "1234;cluster"); InputError quoting the output
// if it holds none.
std::string parsable_job_id(const std::string& sbatch_output);

// The partitions `sinfo -h -o %R` printed, one a line.
std::vector<std::string> partitions_listed(const std::string& sinfo_output);

// Checks the options (check_slurm_options; sbatch on PATH; the partition against sinfo's list when
// sinfo is there), resolves and checks every run (checked_study_runs), claims the folder, writes
// the scripts and submits them. Throws InputError (nothing submitted) for a bad option, a case
// that does not resolve or a refused job; a report job refused after the array was queued cancels
// the array (scancel) before throwing.
SlurmSubmission submit_study_to_slurm(const StudyDefinition& study, const StudyScale& scale,
                                      const std::filesystem::path& out, const std::filesystem::path& preset_directory,
                                      const SlurmOptions& options, const SlurmStudyJobs& jobs);

}  // namespace trapdem
