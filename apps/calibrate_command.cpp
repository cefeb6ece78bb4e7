#include "calibrate_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "plot/figure_format.hpp"
#include "study/slurm_script.hpp"
#include "study/slurm_submission.hpp"
#include "study/study_runner.hpp"
#include "study/study_status.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

namespace {

std::vector<std::string> calibrate_arguments(const CalibrateOptions& o, const fs::path& out) {
  std::vector<std::string> args = {"calibrate", fs::absolute(o.base).lexically_normal().string()};
  for (const std::string& v : o.vary) {
    args.push_back("--vary");
    args.push_back(v);
  }
  args.insert(args.end(), {"--target", fs::absolute(o.target).lexically_normal().string(), "--at", o.at, "--out",
                           fs::absolute(out).lexically_normal().string(), "--grid", o.grid});
  if (!o.piv_trapdoor.empty()) args.insert(args.end(), {"--piv-trapdoor", o.piv_trapdoor});
  if (plot::parse_figure_format(o.format) != plot::FigureFormat::png) args.insert(args.end(), {"--format", o.format});
  return args;
}

std::string command_line(std::vector<std::string> words) {
  words.insert(words.begin(), "trapdem");
  return shell_command(words);
}

}  // namespace

int run_calibrate(const CalibrateCommand& command) {
  const CalibrateOptions& o = command.calibrate;
  if (int(command.status) + int(o.collect) + int(!command.submit.submit.empty()) > 1)
    throw InputError("give one of --collect, --status and --submit");
  if (command.status || !command.submit.submit.empty()) {
    const CalibrationGrid grid = calibration_grid(o);
    const StudyScale& scale = grid.study.scales.front();
    std::vector<std::string> status = calibrate_arguments(o, grid.out);
    status.push_back("--status");
    if (command.status) {
      if (!holds_study(grid.out))
        throw InputError(fmt::format("--status: {} holds no calibration (nothing started there)", grid.out.string()));
      claim_study_folder(grid.study, scale, grid.out);
      fmt::print("calibration '{}' in {}\n{}", grid.study.name, grid.out.string(),
                 status_text(study_status(grid.study, scale, grid.out, {})));
      return 0;
    }
    SlurmStudyJobs jobs;
    jobs.trapdem = this_program();
    jobs.report_arguments = calibrate_arguments(o, grid.out);
    jobs.report_arguments.push_back("--collect");
    jobs.report_arguments.push_back("--quiet");
    jobs.comment = {fmt::format("Calibration '{}': written by `trapdem calibrate ... --submit slurm`.", grid.study.name),
                    "Submitted again by that command, it skips the finished cases and resumes the others; by hand:",
                    "  sbatch array.sbatch, then sbatch --dependency=afterany:<array job id> report.sbatch",
                    fmt::format("Where the cases stand: {}", command_line(status))};
    // The grid's cases name no preset (the scale's base is the file).
    const SlurmSubmission s = submit_study_to_slurm(grid.study, scale, grid.out, {}, command.submit.slurm, jobs);
    print_submission(fmt::format("calibration '{}' submitted", grid.study.name), s.array_script, s.array_job,
                     s.report_job, s.submitted.size(), s.runs, command_line(status));
    return 0;
  }
  const Calibration c = calibrate(o);
  if (!c.complete) {
    fmt::print("calibration interrupted (checkpoint written); run the same command again to carry on\n");
    return kExitInterrupted;
  }
  fmt::print("calibration against {} at {}: {} cases, ranked by RMS(w_DEM - w_PIV)/δ\n", o.target, o.at,
             c.ranked.size());
  std::string head = fmt::format("{:>4}  ", "rank");
  for (const VariedKey& k : c.keys) head += fmt::format("{:>24}  ", k.key);
  fmt::print("{}{:>10}  {:>10}  {:>8}\n", head, "error %", "bias %", "covered");
  for (std::size_t r = 0; r < c.ranked.size(); ++r) {
    std::string line = fmt::format("{:>4}  ", r + 1);
    for (const std::string& v : c.ranked[r].values) line += fmt::format("{:>24}  ", v);
    fmt::print("{}{:>10.3f}  {:>10.3f}  {:>7.0f}%\n", line, 100.0 * c.ranked[r].error, 100.0 * c.ranked[r].bias,
               100.0 * c.ranked[r].coverage);
  }
  const std::string ext = plot::extension_of(plot::parse_figure_format(o.format));
  fmt::print("written in {}: calibration.csv, best.toml (run it with `trapdem run {}`), error_surface{}, "
             "compare_best{}, report/index.html\n", c.out.string(), (c.out / "best.toml").string(), ext, ext);
  return 0;
}

}  // namespace trapdem::app
