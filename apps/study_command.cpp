#include "study_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "core/json.hpp"
#include "io/text_file.hpp"
#include "plot/figure_format.hpp"
#include "run_command.hpp"
#include "study/slurm_script.hpp"
#include "study/slurm_submission.hpp"
#include "study/study_runner.hpp"
#include "study/study_status.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

fs::path this_program() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw FileError(fmt::format("cannot find the trapdem program's own path (/proc/self/exe): {}", ec.message()));
  return self;
}

void print_submission(const std::string& what, const fs::path& array_script, const std::string& array_job,
                      const std::string& report_job, std::size_t submitted, std::size_t runs,
                      const std::string& status_command) {
  if (array_job.empty())
    fmt::print("{}: every run has finished; report job {} submitted\n", what, report_job);
  else
    fmt::print("{}: job array {} ({} of {} runs; script {}), report job {} after it\n", what, array_job, submitted,
               runs, array_script.string(), report_job);
  fmt::print("watch:    squeue -j {}\n", array_job.empty() ? report_job : array_job + "," + report_job);
  fmt::print("progress: {}\n", status_command);
}

int run_study(const StudyOptions& o) {
  const StudyDefinition study = load_study(o.file);
  const StudyScale& scale = study.scale(o.scale.empty() ? study.default_scale : o.scale);
  const fs::path out = o.out.empty() ? fs::path("trapdem-out") / (study.name + "-" + scale.name) : fs::path(o.out);
  const int modes = int(o.report_only) + int(o.collect) + int(o.status) + int(!o.submit.submit.empty());
  if (modes > 1) throw InputError("give one of --report-only, --collect, --status and --submit");
  if (modes > 0 && o.stop_after_seconds > 0.0)
    throw InputError("--stop-after: a budget for the runs here, not for --report-only, --collect, --status or "
                     "--submit (a Slurm task's limit is --time)");
  if (modes > 0 && !(o.cases.empty() && o.seeds.empty()))
    throw InputError("--case, --seed: choose the runs run here, not for --report-only, --collect, --status or "
                     "--submit (the report covers every finished run)");
  if (o.stop_after_seconds < 0.0)  // the command line's check refuses it; a caller of the library may not
    throw InputError(fmt::format("--stop-after: {:g} s: expected a positive number of seconds (0: no budget)",
                                 o.stop_after_seconds));
  const plot::FigureFormat format = plot::parse_figure_format(o.format, "--format");
  const std::vector<std::string> where = {"--out", fs::absolute(out).lexically_normal().string(), "--scale", scale.name};
  std::vector<std::string> status_command = {"trapdem", "study", fs::absolute(o.file).lexically_normal().string()};
  status_command.insert(status_command.end(), where.begin(), where.end());
  status_command.push_back("--status");

  if (o.status) {
    if (!holds_study(out)) throw InputError(fmt::format("--status: {} holds no study (nothing started there)", out.string()));
    claim_study_folder(study, scale, out);  // the folder is this study's
    fmt::print("study '{}' at scale '{}' in {}\n{}", study.name, scale.name, out.string(),
               status_text(study_status(study, scale, out, preset_directory())));
    return 0;
  }
  if (!o.submit.submit.empty()) {
    SlurmStudyJobs jobs;
    jobs.trapdem = this_program();
    jobs.report_arguments = {"study", fs::absolute(o.file).lexically_normal().string()};
    jobs.report_arguments.insert(jobs.report_arguments.end(), where.begin(), where.end());
    jobs.report_arguments.push_back("--collect");
    jobs.report_arguments.push_back("--quiet");
    if (format != plot::FigureFormat::png) jobs.report_arguments.insert(jobs.report_arguments.end(), {"--format", o.format});
    jobs.comment = {fmt::format("Study '{}' at scale '{}': written by `trapdem study ... --submit slurm`.", study.name,
                                scale.name),
                    "Submitted again by that command, it skips the finished runs and resumes the others; by hand:",
                    "  sbatch array.sbatch, then sbatch --dependency=afterany:<array job id> report.sbatch",
                    fmt::format("Where the runs stand: {}", shell_command(status_command))};
    const SlurmSubmission s = submit_study_to_slurm(study, scale, out, preset_directory(), o.submit.slurm, jobs);
    print_submission(fmt::format("study '{}' submitted", study.name), s.array_script, s.array_job, s.report_job,
                     s.submitted.size(), s.runs, shell_command(status_command));
    return 0;
  }
  if (o.report_only || o.collect) {
    if (!holds_study(out))
      throw InputError(fmt::format("{}: {} holds no study", o.collect ? "--collect" : "--report-only", out.string()));
    claim_study_folder(study, scale, out);
    if (o.collect) {
      // The runs ran elsewhere (a Slurm array); what is left for one process: the element tests.
      const StudyRunSettings settings{preset_directory(), o.threads, o.quiet, {}};
      checked_study_runs(study, scale, out, settings.preset_directory);
      if (study.report.element_test)
        for (const StudyCase& c : study.cases) run_case_element_test_once(study, c, scale, out, settings);
      const std::vector<RunStatus> runs = study_status(study, scale, out, preset_directory());
      for (const RunStatus& r : runs)
        if (r.state != RunState::finished)
          log_study_line(out, fmt::format("collect: {} has not finished ({}); the report leaves it out", r.title,
                                          to_string(r.state)), false);
    }
  } else {
    StudyRunSettings settings{preset_directory(), o.threads, o.quiet, {}};
    settings.stop_after_seconds = o.stop_after_seconds;
    settings.only = {o.cases, o.seeds};
    if (!run_study_in_folder(study, scale, out, settings)) return kExitInterrupted;
  }
  const fs::path page = write_study_outputs(study, scale, out, o.quiet, preset_directory(), format);
  log_study_line(out, fmt::format("report: {}", page.string()), o.quiet);
  if (!o.quiet) {
    const Json summary = Json::parse(read_text_file(page.parent_path() / "summary.json"));
    for (std::size_t k = 0; k < summary["findings"].size(); ++k)
      fmt::print("  - {}\n", summary["findings"][k].as_string());
  }
  return 0;
}

}  // namespace trapdem::app
