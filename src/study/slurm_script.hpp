#pragma once
// The sbatch scripts of a study submitted to Slurm (issue 16, docs/study.md "On a cluster"), as text
// from plain structs: the job array (a task per run of the study, each `trapdem run` into its case
// folder, resuming from the folder when it holds a run) and the report job. Kept in the study
// folder, readable, for a user to adapt and submit by hand.
#include <filesystem>
#include <string>
#include <vector>

#include "study/slurm_options.hpp"

namespace trapdem {

// One run of the study as an array task.
struct SlurmScriptTask {
  int index = 0;                        // the array index: the run's place in the study (1-based)
  std::string title;                    // "smooth", "rf1 seed 2020"
  std::filesystem::path dir;            // the run's folder (absolute)
  std::filesystem::path config;         // the configuration it starts from (absolute)
  std::vector<std::string> overrides;   // its --set assignments, in order
};

struct SlurmArrayScript {
  std::string job_name;                 // e.g. "trapdem-tiny-pair"
  std::vector<std::string> comment;     // lines for the head of the script (what it is, how it was made)
  std::filesystem::path trapdem;        // the trapdem program (absolute)
  std::filesystem::path log_folder;     // where Slurm writes each task's output (absolute)
  SlurmOptions options;
  std::vector<int> array;               // the tasks to run (--array): the runs not finished
  std::vector<SlurmScriptTask> tasks;   // every run of the study, finished or not
};

struct SlurmReportScript {
  std::string job_name;
  std::vector<std::string> comment;
  std::filesystem::path trapdem;
  std::filesystem::path log_folder;
  SlurmOptions options;
  std::vector<std::string> arguments;   // trapdem's arguments (`--threads` is added from the job's CPUs)
};

// The array script: #SBATCH lines (job name, array, CPUs, partition, time, output, the options
// given), then a `case` on SLURM_ARRAY_TASK_ID with one branch per task. A task's run resumes from
// its folder when the folder holds one (`trapdem run --resume`: from checkpoint.h5, or from the start
// for a run stopped before its first checkpoint), is skipped when run.json says it finished, and
// starts `trapdem run CONFIG --set ... --out DIR` otherwise; `exec` makes trapdem the job's process,
// so Slurm's SIGTERM (scancel, or --signal before the time limit) reaches it and it checkpoints.
std::string array_script_text(const SlurmArrayScript& script);

// The report job's script: trapdem with `arguments` and --threads from SLURM_CPUS_PER_TASK.
std::string report_script_text(const SlurmReportScript& script);

// `text` as one shell word ('...' with embedded quotes escaped); plain words as they are.
std::string shell_quoted(const std::string& text);

// Words as one shell command line, each shell_quoted, separated by spaces.
std::string shell_command(const std::vector<std::string>& words);

// Array indices as sbatch --array writes them: ascending, runs of consecutive ones as "a-b" ("1-3,5").
std::string array_ranges(std::vector<int> indices);

}  // namespace trapdem
