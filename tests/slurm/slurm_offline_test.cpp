// What a Slurm submission writes and reads without a cluster (issue 16): the array script run by
// bash with a stand-in for trapdem (what each task would run: a new run, a resume, a skip, with
// every --set word intact), the report script, the option checks, sbatch's and sinfo's output
// read back, and `--status` on study folders made by hand in each state.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "../study/tiny_study.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_record.hpp"
#include "io/text_file.hpp"
#include "study/calibration.hpp"
#include "study/slurm_options.hpp"
#include "study/slurm_script.hpp"
#include "study/slurm_submission.hpp"
#include "study/study_runner.hpp"
#include "study/study_status.hpp"
#include "study_command.hpp"
#include "../io/io_test_support.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

// In a folder of this process's own, removed at its exit (a failed test's too).
fs::path scratch(const std::string& name) {
  static const io_testing::ScratchDir root("trapdem-slurm");
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A stand-in for trapdem: writes its arguments, one a line, to args.txt beside it.
fs::path stand_in(const fs::path& dir) {
  const fs::path program = dir / "trapdem-stand-in";
  write(program, "#!/bin/bash\nprintf '%s\\n' \"$@\" > \"$(dirname \"$0\")/args.txt\"\n");
  fs::permissions(program, fs::perms::owner_all);
  return program;
}

// Runs `script` with bash as array task `task` with 3 CPUs; returns bash's exit code.
int run_as_task(const fs::path& script, const std::string& task, const fs::path& output) {
  const std::string command = "env SLURM_ARRAY_TASK_ID=" + task + " SLURM_CPUS_PER_TASK=3 bash " + script.string() +
                              " > " + output.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Overrides with what a shell would break: spaces, double and single quotes, brackets, a '$'.
const std::vector<std::string> kAwkwardOverrides = {
    "output.snapshot_displacements=[0.0, 0.001, 0.002]", "name=\"smooth grains\"",
    "description='it''s $HOME'", "contact.kinetic_friction=0.2"};

SlurmArrayScript example_array(const fs::path& dir) {
  SlurmArrayScript a;
  a.job_name = "trapdem-tiny pair";
  a.comment = {"An example.", "", "Second paragraph."};
  a.trapdem = stand_in(dir);
  a.log_folder = dir / "slurm";
  a.options.cpus_per_task = 3;
  a.options.partition = "short";
  a.options.time = "1-00:00:00";
  a.options.sbatch_args = {"--account=geo", "--qos=long"};
  a.array = {2, 3};
  for (int k = 1; k <= 3; ++k) {
    SlurmScriptTask t;
    t.index = k;
    t.title = "case " + std::to_string(k);
    t.dir = dir / "cases" / ("case-" + std::to_string(k));
    t.config = dir / "base config.toml";
    t.overrides = kAwkwardOverrides;
    a.tasks.push_back(t);
  }
  return a;
}

std::string error_of_options(const SlurmOptions& o) {
  try {
    check_slurm_options(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(SlurmScript, ArrayScriptParsesAndHoldsEveryOption) {
  const fs::path dir = scratch("array-text");
  const SlurmArrayScript a = example_array(dir);
  const fs::path script = dir / "array.sbatch";
  write(script, array_script_text(a));
  EXPECT_EQ(std::system(("bash -n " + script.string()).c_str()), 0) << read_text_file(script);
  const std::string text = read_text_file(script);
  for (const char* line : {"#SBATCH --job-name='trapdem-tiny pair'\n", "#SBATCH --cpus-per-task=3\n",
                           "#SBATCH --partition=short\n", "#SBATCH --time=1-00:00:00\n", "#SBATCH --array=2-3\n",
                           "#SBATCH --account=geo\n", "#SBATCH --qos=long\n", "#SBATCH --open-mode=append\n",
                           "#SBATCH --signal=B:TERM@300\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line;
  // Every run is listed (finished ones too: a hand-made --array may name them), each with its title.
  for (int k = 1; k <= 3; ++k)
    EXPECT_NE(text.find(std::to_string(k) + ")  # case " + std::to_string(k)), std::string::npos) << k;
  // sbatch reads #SBATCH lines only before the first command.
  const std::size_t last_directive = text.rfind("#SBATCH"), first_command = text.find("\nset -euo pipefail");
  EXPECT_LT(last_directive, first_command);
  fs::remove_all(dir);
}

TEST(SlurmScript, ATaskStartsResumesOrSkipsItsRunByItsFolder) {
  const fs::path dir = scratch("array-run");
  const SlurmArrayScript a = example_array(dir);
  const fs::path script = dir / "array.sbatch", args = dir / "args.txt", output = dir / "task.out";
  write(script, array_script_text(a));

  // A new run: the configuration, its folder, the job's CPUs as threads, every override word intact.
  ASSERT_EQ(run_as_task(script, "2", output), 0) << read_text_file(output);
  std::vector<std::string> expected = {"run", (dir / "base config.toml").string(), "--out",
                                       (dir / "cases" / "case-2").string(), "--threads", "3", "--quiet"};
  for (const std::string& o : kAwkwardOverrides) {
    expected.push_back("--set");
    expected.push_back(o);
  }
  EXPECT_EQ(lines_of(read_text_file(args)), expected);

  // A folder holding a run (a checkpoint, or resolved.toml of a run stopped before its first one):
  // the task resumes it, as a requeued or resubmitted task must.
  write(dir / "cases" / "case-2" / "checkpoint.h5", "");
  ASSERT_EQ(run_as_task(script, "2", output), 0) << read_text_file(output);
  EXPECT_EQ(lines_of(read_text_file(args)),
            (std::vector<std::string>{"run", "--resume", (dir / "cases" / "case-2").string(), "--threads", "3",
                                      "--quiet"}));
  write(dir / "cases" / "case-3" / "resolved.toml", "");
  ASSERT_EQ(run_as_task(script, "3", output), 0) << read_text_file(output);
  EXPECT_EQ(lines_of(read_text_file(args))[1], "--resume");

  // A finished run: nothing runs.
  fs::remove(args);
  record_run_segment(RunFolder(dir / "cases" / "case-2"), RunSegment{true, "done", 1.0, 10, 100.0, 10});
  ASSERT_EQ(run_as_task(script, "2", output), 0) << read_text_file(output);
  EXPECT_FALSE(fs::exists(args));
  EXPECT_NE(read_text_file(output).find("finished before, nothing to do"), std::string::npos);

  // A task the script does not have: an error, not a silent success.
  EXPECT_EQ(run_as_task(script, "9", output), 2);
  EXPECT_NE(read_text_file(output).find("not a task of this script (1-3)"), std::string::npos);
  fs::remove_all(dir);
}

TEST(SlurmScript, ReportScriptRunsTrapdemWithTheJobsCpus) {
  const fs::path dir = scratch("report");
  SlurmReportScript r;
  r.job_name = "trapdem-x-report";
  r.trapdem = stand_in(dir);
  r.log_folder = dir / "slurm";
  r.arguments = {"study", (dir / "my study.toml").string(), "--out", (dir / "out").string(), "--collect", "--quiet"};
  const fs::path script = dir / "report.sbatch";
  write(script, report_script_text(r));
  EXPECT_EQ(std::system(("bash -n " + script.string()).c_str()), 0);
  EXPECT_EQ(read_text_file(script).find("--array"), std::string::npos);
  ASSERT_EQ(run_as_task(script, "", dir / "report.out"), 0) << read_text_file(dir / "report.out");
  std::vector<std::string> expected = r.arguments;
  expected.insert(expected.end(), {"--threads", "3"});
  EXPECT_EQ(lines_of(read_text_file(dir / "args.txt")), expected);
  fs::remove_all(dir);
}

TEST(SlurmScript, ArrayRangesAndShellWords) {
  EXPECT_EQ(array_ranges({5, 1, 2, 3, 7, 8, 2}), "1-3,5,7-8");
  EXPECT_EQ(array_ranges({4}), "4");
  EXPECT_EQ(shell_quoted("cases/rf1"), "cases/rf1");
  EXPECT_EQ(shell_quoted("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quoted(""), "''");
  EXPECT_EQ(shell_command({"trapdem", "study", "a b.toml"}), "trapdem study 'a b.toml'");
}

TEST(SlurmOptions, TimeLimitsInSlurmsForms) {
  EXPECT_EQ(slurm_time_seconds("90"), 90 * 60);
  EXPECT_EQ(slurm_time_seconds("5:30"), 5 * 60 + 30);
  EXPECT_EQ(slurm_time_seconds("12:00:00"), 12 * 3600);
  EXPECT_EQ(slurm_time_seconds("2-12"), (2 * 24 + 12) * 3600);
  EXPECT_EQ(slurm_time_seconds("1-0:30"), 24 * 3600 + 30 * 60);
  EXPECT_EQ(slurm_time_seconds("1-00:00:10"), 24 * 3600 + 10);
  for (const char* bad : {"", "abc", "1h", "1:60", "1:60:00", "0", "00:00:00", "1-24", "1:2:3:4", "-5", "1.5"}) {
    try {
      slurm_time_seconds(bad);
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--time '" + std::string(bad) + "'"), std::string::npos) << e.what();
    }
  }
}

TEST(SlurmOptions, BadOptionsNameTheOption) {
  SlurmOptions o;
  EXPECT_EQ(error_of_options(o), "(no error)");
  o.cpus_per_task = 0;
  EXPECT_NE(error_of_options(o).find("--cpus-per-task 0: expected a whole number from 1"), std::string::npos);
  o.cpus_per_task = 2;
  o.partition = "a b";
  EXPECT_NE(error_of_options(o).find("--partition 'a b'"), std::string::npos);
  o.partition = "gpu-long";
  EXPECT_EQ(error_of_options(o), "(no error)");
  for (const char* own : {"--array=1-3", "--dependency=afterok:1", "-c4", "--output=x", "--time=1:00"}) {
    o.sbatch_args = {own};
    EXPECT_NE(error_of_options(o).find("is set by trapdem itself"), std::string::npos) << own;
  }
  o.sbatch_args = {"account=geo"};
  EXPECT_NE(error_of_options(o).find("expected one sbatch option"), std::string::npos);
  o.sbatch_args = {"--qos=long\n--array=1"};
  EXPECT_NE(error_of_options(o).find("expected one sbatch option"), std::string::npos);
  o.sbatch_args = {"--account=geo", "--qos=long", "--mem=4G", "--requeue"};
  EXPECT_EQ(error_of_options(o), "(no error)");

  EXPECT_NO_THROW(check_partition_known("", {}));
  EXPECT_NO_THROW(check_partition_known("debug", {"debug", "long"}));
  try {
    check_partition_known("nope", {"debug", "long"});
    ADD_FAILURE() << "unknown partition accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sinfo lists: debug, long"), std::string::npos) << e.what();
  }
}

TEST(SlurmOutput, JobIdsAndPartitionsReadBack) {
  EXPECT_EQ(parsable_job_id("4711\n"), "4711");
  EXPECT_EQ(parsable_job_id("4711;cluster-a\n"), "4711");
  EXPECT_THROW(parsable_job_id(""), InputError);
  EXPECT_THROW(parsable_job_id("Submitted batch job 4711\n"), InputError);
  EXPECT_EQ(partitions_listed("debug\nlong\n\ndebug\n"), (std::vector<std::string>{"debug", "long"}));
}

// --status on a study folder made by hand, each run in one state. The log lines are those
// experiment/folder_run.cpp and run_recorder.cpp write (the cluster test reads a real stopped run).
TEST(StudyStatus, EachStateFromTheFolderAlone) {
  const fs::path dir = scratch("status");
  write(dir / "study.toml", R"(name = "states"
[scales.test]
preset = "tiny"
[cases.fresh]
label = "Fresh"
[cases.going]
label = "Going"
[cases.halted]
label = "Halted"
[cases.done]
label = "Done"
[cases.broken]
label = "Broken"
)");
  const fs::path out = dir / "out";
  const StudyDefinition study = load_study(dir / "study.toml");
  const StudyScale& scale = study.scale("test");
  fs::create_directories(out);
  claim_study_folder(study, scale, out);
  const std::string head = "trapdem run 'going': tiny\n  output in x\n";
  write(out / "cases" / "going" / "resolved.toml", "");
  write(out / "cases" / "going" / "run.log",
        head + "[pluviation]  100.0%  t = 0.1000 s    1.00 M particle-steps/s  left      0 s  poured\n"
               "stage pluviation finished at t = 0.1000 s (step 100): ...\n"
               "[settling  ]   42.5%  t = 0.1200 s    1.00 M particle-steps/s  left      3 s  ke 1e-6\n");
  write(out / "cases" / "halted" / "run.log",
        head + "[lowering  ]   12.0%  t = 0.3000 s    1.00 M particle-steps/s  left     20 s  load 0.5\n"
               "stopped (checkpoint written; carry on with --resume) after 5 s of wall clock: 10 steps, 100 particles, "
               "1.00 M particle-steps/s\n");
  write(out / "cases" / "done" / "run.log", head);
  record_run_segment(RunFolder(out / "cases" / "done"), RunSegment{true, "done", 1.0, 10, 100.0, 10});
  write(out / "cases" / "broken" / "run.log",
        head + "[settling  ]    3.0%  t = 0.1000 s    1.00 M particle-steps/s  left      3 s  ke 1\n"
               "stopped by an error: particle 12 escaped the domain at step 40\n");

  const std::vector<RunStatus> runs = study_status(study, scale, out, fs::path(TRAPDEM_SOURCE_DIR) / "presets");
  ASSERT_EQ(runs.size(), 5u);
  EXPECT_EQ(runs[0].state, RunState::not_started);
  EXPECT_EQ(runs[1].state, RunState::running);
  EXPECT_EQ(runs[1].stage, "settling");
  EXPECT_DOUBLE_EQ(runs[1].percent, 42.5);
  EXPECT_EQ(runs[2].state, RunState::stopped);
  EXPECT_EQ(runs[2].stage, "lowering");
  EXPECT_EQ(runs[3].state, RunState::finished);
  EXPECT_EQ(runs[4].state, RunState::failed);
  EXPECT_EQ(runs[4].last_line, "stopped by an error: particle 12 escaped the domain at step 40");

  // The command prints a line per run and the count per state.
  app::StudyOptions o;
  o.file = (dir / "study.toml").string();
  o.out = out.string();
  o.status = true;
  testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_study(o), 0);
  const std::string printed = testing::internal::GetCapturedStdout();
  for (const char* expected : {"fresh   not started", "going   running: settling 42.5 %", "halted  stopped with a checkpoint at lowering 12.0 %",
                               "done    finished", "broken  failed: stopped by an error: particle 12 escaped",
                               "5 runs: 1 finished, 1 running, 1 stopped, 1 failed, 1 not started"})
    EXPECT_NE(printed.find(expected), std::string::npos) << expected << "\n" << printed;
  // --status runs nothing and needs no Slurm: the folders are as they were.
  EXPECT_FALSE(fs::exists(out / "cases" / "fresh"));
  EXPECT_FALSE(fs::exists(out / "report"));
  fs::remove_all(dir);
}

TEST(StudyStatus, AFolderWithoutAStudyIsAnError) {
  const fs::path dir = scratch("status-none");
  write(dir / "study.toml", "name = \"s\"\n[scales.test]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n");
  app::StudyOptions o;
  o.file = (dir / "study.toml").string();
  o.out = (dir / "nothing").string();
  o.status = true;
  try {
    app::run_study(o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no study"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// The report job's --collect: no trapdoor run starts; the element tests still missing run
// (report.element_test, shrunk as in the replicate study test: ~10 s on one thread), and the report
// is written with the unfinished run left out and named in study.log.
TEST(Collect, RunsTheElementTestsAndReportsWithoutStartingARun) {
  const fs::path dir = scratch("collect");
  write(dir / "study.toml", "name = \"collect\"\n[scales.test]\npreset = \"tiny\"\n[scales.test.set]\n"
                            "contact.restitution = 0.9\n[report]\n" + test::small_element_test +
                            "[cases.only]\nlabel = \"Only\"\n");
  const fs::path out = dir / "out";
  app::StudyOptions o;
  o.file = (dir / "study.toml").string();
  o.out = out.string();
  o.threads = 1;
  o.quiet = true;
  o.collect = true;
  EXPECT_THROW(app::run_study(o), InputError);  // no study there yet
  const StudyDefinition study = load_study(dir / "study.toml");
  fs::create_directories(out);
  claim_study_folder(study, study.scale("test"), out);
  ASSERT_EQ(app::run_study(o), 0);
  EXPECT_FALSE(fs::exists(out / "cases" / "only" / "run.log"));  // no run started
  EXPECT_TRUE(fs::exists(out / "cases" / "only" / "element" / "element.json"));
  EXPECT_TRUE(fs::exists(out / "report" / "summary.json"));
  const std::string log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("collect: only has not finished (not started); the report leaves it out"), std::string::npos) << log;
  EXPECT_NE(log.find("only element test: finished"), std::string::npos) << log;
  fs::remove_all(dir);
}

// A calibration's --collect ranks only a complete grid: otherwise it names the cases missing.
TEST(Collect, CalibrationNamesTheCasesNotFinished) {
  const fs::path dir = scratch("collect-calibration");
  fs::copy_file(fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml", dir / "base.toml");
  write(dir / "piv" / "piv.h5", "");
  CalibrateOptions o;
  o.base = (dir / "base.toml").string();
  o.vary = {"contact.kinetic_friction=0.2,0.5"};
  o.target = (dir / "piv").string();
  o.at = "2mm";
  o.out = (dir / "out").string();
  o.collect = true;
  const CalibrationGrid grid = calibration_grid(o);
  fs::create_directories(grid.out);
  claim_study_folder(grid.study, grid.study.scales.front(), grid.out);
  fs::create_directories(grid.out / "cases" / "kinetic_friction-0.2");
  record_run_segment(RunFolder(grid.out / "cases" / "kinetic_friction-0.2"), RunSegment{true, "done", 1.0, 1, 1.0, 1});
  try {
    calibrate(o);
    ADD_FAILURE() << "an incomplete grid was ranked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(kinetic_friction-0.5 not finished"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}
