#include "study/slurm_submission.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/trimmed.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_record.hpp"
#include "io/atomic_file.hpp"
#include "study/cluster_process.hpp"
#include "study/slurm_script.hpp"
#include "study/study_runner.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// What a failed Slurm command said, on one line for a message.
std::string said(const ProcessResult& r) {
  std::string text = trimmed(r.errors.empty() ? r.output : r.errors);
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.empty() ? fmt::format("exit code {}, no message", r.exit_code) : text;
}

// Asks sinfo for the partitions when sinfo is there (a login node without it: sbatch decides).
void check_partition_with_sinfo(const std::string& partition) {
  if (partition.empty() || !program_on_path("sinfo")) return;
  const ProcessResult r = run_process({"sinfo", "-h", "-o", "%R"});
  if (r.exit_code != 0)
    throw InputError(fmt::format("--partition {}: cannot ask Slurm for its partitions (sinfo: {})", partition, said(r)));
  check_partition_known(partition, partitions_listed(r.output));
}

std::string submit(const std::vector<std::string>& argv, const std::string& what) {
  const ProcessResult r = run_process(argv);
  if (r.exit_code != 0) throw InputError(fmt::format("sbatch refused {}: {}", what, said(r)));
  return parsable_job_id(r.output);
}

}  // namespace

std::string parsable_job_id(const std::string& output) {
  const std::string line = trimmed(output.substr(0, output.find('\n')));
  const std::string id = line.substr(0, line.find(';'));
  if (id.empty() || !std::all_of(id.begin(), id.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw InputError(fmt::format("sbatch --parsable printed '{}', not a job id", trimmed(output)));
  return id;
}

std::vector<std::string> partitions_listed(const std::string& output) {
  std::vector<std::string> names;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    line = trimmed(line);
    if (!line.empty() && std::find(names.begin(), names.end(), line) == names.end()) names.push_back(line);
  }
  return names;
}

SlurmSubmission submit_study_to_slurm(const StudyDefinition& study, const StudyScale& scale, const fs::path& out_given,
                                      const fs::path& presets, const SlurmOptions& options,
                                      const SlurmStudyJobs& jobs) {
  check_slurm_options(options);
  if (!program_on_path("sbatch"))
    throw InputError("--submit slurm: sbatch is not on PATH (Slurm's client commands; submit from a login node of "
                     "the cluster, or install Debian's slurm-client)");
  check_partition_with_sinfo(options.partition);

  // As a local study: every run resolved and checked before anything is written or queued.
  const fs::path out = fs::absolute(out_given).lexically_normal();
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw FileError(fmt::format("cannot create the study folder {}: {}", out.string(), ec.message()));
  claim_study_folder(study, scale, out);
  const std::vector<std::vector<CaseRun>> runs = checked_study_runs(study, scale, out, presets);

  SlurmSubmission s;
  const fs::path slurm_dir = out / "slurm";
  fs::create_directories(slurm_dir, ec);
  if (ec) throw FileError(fmt::format("cannot create {}: {}", slurm_dir.string(), ec.message()));

  SlurmArrayScript array;
  array.job_name = "trapdem-" + study.name;
  array.comment = jobs.comment;
  array.trapdem = jobs.trapdem;
  array.log_folder = slurm_dir;
  array.options = options;
  for (std::size_t k = 0; k < study.cases.size(); ++k)
    for (const CaseRun& run : runs[k]) {
      SlurmScriptTask task;
      task.index = int(++s.runs);
      task.title = run_title(study.cases[k], run);
      task.dir = run.dir;
      task.config = fs::absolute(case_base_file(run, presets)).lexically_normal();
      task.overrides = run.recipe.overrides;
      if (!run_finished(RunFolder(run.dir))) {
        array.array.push_back(task.index);
        s.submitted.push_back(task.title);
      }
      array.tasks.push_back(std::move(task));
    }
  SlurmReportScript report;
  report.job_name = array.job_name + "-report";
  report.comment = jobs.comment;
  report.trapdem = jobs.trapdem;
  report.log_folder = slurm_dir;
  report.options = options;
  report.arguments = jobs.report_arguments;

  s.array_script = slurm_dir / "array.sbatch";
  s.report_script = slurm_dir / "report.sbatch";
  // Written whatever is submitted: with every run finished it lists them all (each task then skips).
  SlurmArrayScript written = array;
  if (written.array.empty())
    for (const SlurmScriptTask& t : written.tasks) written.array.push_back(t.index);
  write_text_atomically(s.array_script, array_script_text(written));
  write_text_atomically(s.report_script, report_script_text(report));

  if (!array.array.empty()) s.array_job = submit({"sbatch", "--parsable", s.array_script.string()}, "the job array");
  try {
    std::vector<std::string> argv = {"sbatch", "--parsable"};
    if (!s.array_job.empty()) argv.push_back("--dependency=afterany:" + s.array_job);
    argv.push_back(s.report_script.string());
    s.report_job = submit(argv, "the report job");
  } catch (const InputError& e) {
    if (!s.array_job.empty()) {
      const ProcessResult r = run_process({"scancel", s.array_job});
      throw InputError(fmt::format("{}; the job array {} it depends on was {}", e.what(), s.array_job,
                                   r.exit_code == 0 ? "cancelled (scancel): nothing of this study is queued"
                                                    : "not cancelled (scancel: " + said(r) + "): cancel it by hand"));
    }
    throw;
  }
  log_study_line(out,
                 s.array_job.empty()
                     ? fmt::format("submitted to Slurm: every run had finished; report job {}", s.report_job)
                     : fmt::format("submitted to Slurm: job array {} ({} of {} runs: tasks {}), report job {} after it",
                                   s.array_job, s.submitted.size(), s.runs, array_ranges(array.array), s.report_job),
                 true);
  return s;
}

}  // namespace trapdem
