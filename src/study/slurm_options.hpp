#pragma once
// What `--submit slurm` takes from the command line (--partition, --time, --cpus-per-task,
// --sbatch-arg) and its checks, made before anything is submitted (issue 16): a mistake is our
// clear error naming the option, not a job that fails in the queue hours later.
#include <cstdint>
#include <string>
#include <vector>

namespace trapdem {

struct SlurmOptions {
  std::string partition;                 // empty: the cluster's default partition
  std::string time;                      // a Slurm time limit per array task (and the report job); empty: the partition's
  int cpus_per_task = 1;                 // CPUs of each array task: its run's --threads
  std::vector<std::string> sbatch_args;  // further sbatch options, each "--name=value" (account, QoS, ...)
};

// A Slurm time limit ("minutes", "minutes:seconds", "hours:minutes:seconds", "days-hours",
// "days-hours:minutes", "days-hours:minutes:seconds", as sbatch --time takes it) in seconds.
// Throws InputError naming --time and the forms for any other text, and for a limit of zero.
std::int64_t slurm_time_seconds(const std::string& text);

// Checks the options on their own (no Slurm asked): --cpus-per-task >= 1 (and at most 4096),
// --time in a Slurm form, --partition a plain name, each --sbatch-arg an option ("-..." on one
// line) that is not one of those this submission sets itself (--array, --dependency,
// --cpus-per-task, --partition, --time, --output, --job-name, --parsable). InputError otherwise.
void check_slurm_options(const SlurmOptions& options);

// `partition` against the partitions Slurm lists (sinfo's): InputError naming them if it is not
// one of them. An empty partition is always accepted (the cluster's default).
void check_partition_known(const std::string& partition, const std::vector<std::string>& known);

}  // namespace trapdem
