// Studies submitted to a real Slurm (issue 16): a one-node cluster that tests/slurm/cluster.sh
// starts for these tests (ctest fixture slurm_cluster; SLURM_CONF points at it). The trapdem
// command runs as a process, as a user runs it, so the job scripts name the real program.
//  - a two-case tiny study submitted ends with the same summary.json numbers as the study run here;
//    the report job started after every array task had ended (jobcomp's times);
//  - a case cancelled with scancel mid-run stops with a checkpoint, shows as stopped in --status,
//    and the study submitted again resumes it (run.log says so) and finishes;
//  - bad options (unknown partition, zero CPUs, a bad time, an option of ours in --sbatch-arg, a
//    case that does not resolve) are our error, and nothing is queued or written;
//  - a calibration grid is submitted the same way (its cases as the array, the ranking after it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/json.hpp"
#include "experiment/run_folder.hpp"
#include "experiment/run_record.hpp"
#include "io/text_file.hpp"
#include "study/cluster_process.hpp"
#include "../study/tiny_study.hpp"
#include "study_command.hpp"
#include "../io/io_test_support.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

// Two tiny cases differing in sliding friction, shortened as the study tests shorten them.
const std::string kScale = test::tiny_scale("the tiny preset, a shallow pour and a short travel");
const std::string kStudy = "name = \"slurm-pair\"\n" + kScale + test::three_mm_of_travel + "[report]\ncontours_at = 0.002\n" +
                           test::smooth_and_rough_cases;

// In a folder of this process's own, removed at its exit (a failed test's too).
fs::path scratch(const std::string& name) {
  static const io_testing::ScratchDir root("trapdem-slurm");
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write_file(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

ProcessResult trapdem_command(std::vector<std::string> args) {
  args.insert(args.begin(), TRAPDEM_EXECUTABLE);
  return run_process(args);
}

// The node's state and, when it is drained or down, sinfo's reason (slurmd's, e.g. a step socket
// it could not create): "idle none", "drain batch job complete failure", ...
std::string node_state() { return run_process({"sinfo", "-h", "-o", "%t %E"}).output; }

// A node that cannot launch jobs: they are requeued and would stay PENDING for ever.
bool node_cannot_run_jobs() {
  const std::string state = node_state();
  for (const char* bad : {"drain", "drng", "down", "fail"})
    if (state.rfind(bad, 0) == 0) return true;
  return false;
}

std::string queue() { return run_process({"squeue", "-h", "-o", "%i %j %T"}).output; }

// For a failed wait's message: the queue, and the node's state and reason.
std::string queue_and_node() { return queue() + "node (sinfo %t %E): " + node_state(); }

// Waits until the cluster's queue is empty (every job of the test ended); false after `seconds`,
// or at once when the node cannot launch jobs (queue_and_node() then says why).
bool queue_empties_within(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (node_cannot_run_jobs()) return false;
    const ProcessResult r = run_process({"squeue", "-h", "-o", "%i"});
    if (r.exit_code == 0 && r.output.empty()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  return false;
}

// The job ids a submission printed: "job array A (...), report job R after it".
struct SubmittedJobs {
  std::string array, report;
};
SubmittedJobs jobs_printed(const std::string& output) {
  SubmittedJobs j;
  std::smatch m;
  if (std::regex_search(output, m, std::regex(R"(job array (\d+) )"))) j.array = m[1];
  if (std::regex_search(output, m, std::regex(R"(report job (\d+))"))) j.report = m[1];
  return j;
}

// The finished jobs as jobcomp/filetxt recorded them (cluster.sh: DIR/jobcomp.txt), each line's
// KEY=VALUE words.
std::vector<std::map<std::string, std::string>> finished_jobs() {
  std::vector<std::map<std::string, std::string>> jobs;
  std::istringstream lines(read_text_file(fs::path(TRAPDEM_SLURM_CLUSTER) / "jobcomp.txt"));
  for (std::string line; std::getline(lines, line);) {
    std::map<std::string, std::string> job;
    std::istringstream words(line);
    for (std::string w; words >> w;)
      if (const auto eq = w.find('='); eq != std::string::npos) job[w.substr(0, eq)] = w.substr(eq + 1);
    jobs.push_back(job);
  }
  return jobs;
}

Json summary_of(const fs::path& out) {
  const fs::path file = out / "report" / "summary.json";
  return Json::parse(read_text_file(file), file.string());
}

// The report's numbers and findings; the run costs (wall clock, segments) left out.
std::string measured(const Json& summary) {
  Json cases = Json::array();
  for (std::size_t k = 0; k < summary["cases"].size(); ++k) {
    Json c = summary["cases"][k];
    Json kept = Json::object();
    for (const auto& [key, value] : c.members())
      if (key != "cost") kept.set(key, value);
    cases.push_back(kept);
  }
  Json j = Json::object();
  j.set("cases", cases);
  j.set("findings", summary["findings"]);
  return j.dump();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    // Slurm's commands, here and in the trapdem processes, talk to the fixture's cluster.
    ::setenv("SLURM_CONF", (fs::path(TRAPDEM_SLURM_CLUSTER) / "slurm.conf").c_str(), 1);
    // The fixture's cluster answers, and nothing of an earlier test is left in its queue.
    const ProcessResult r = run_process({"sinfo", "-h", "-o", "%R %t"});
    ASSERT_EQ(r.exit_code, 0) << "the test cluster does not answer (slurm.cluster_start failed?): " << r.errors;
    ASSERT_TRUE(queue_empties_within(60)) << "jobs left in the queue: " << queue_and_node();
  }
};

}  // namespace

TEST_F(SlurmCluster, SubmittedStudyEndsWithTheNumbersOfALocalRun) {
  const fs::path dir = scratch("pair");
  const fs::path file = write_file(dir / "study.toml", kStudy);
  const fs::path out = dir / "on-slurm";
  const ProcessResult submitted =
      trapdem_command({"study", file.string(), "--out", out.string(), "--submit", "slurm", "--cpus-per-task", "1"});
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output << submitted.errors;
  const SubmittedJobs jobs = jobs_printed(submitted.output);
  ASSERT_FALSE(jobs.array.empty()) << submitted.output;
  ASSERT_FALSE(jobs.report.empty()) << submitted.output;
  EXPECT_TRUE(contains(submitted.output, "(2 of 2 runs;")) << submitted.output;
  EXPECT_TRUE(contains(submitted.output, "watch:    squeue -j " + jobs.array + "," + jobs.report)) << submitted.output;
  EXPECT_TRUE(contains(submitted.output, "--status")) << submitted.output;

  // The script kept in the folder: valid bash, every case listed with its folder.
  const fs::path script = out / "slurm" / "array.sbatch";
  EXPECT_EQ(run_process({"bash", "-n", script.string()}).exit_code, 0);
  const std::string text = read_text_file(script);
  EXPECT_TRUE(contains(text, "1)  # smooth\n    run_case " + (out / "cases" / "smooth").string())) << text;
  EXPECT_TRUE(contains(text, "2)  # rough\n    run_case " + (out / "cases" / "rough").string())) << text;
  EXPECT_TRUE(contains(text, "#SBATCH --array=1-2\n")) << text;

  // The same study here, one thread a run as each task has one CPU, while the cluster runs it.
  app::StudyOptions here;
  here.file = file.string();
  here.out = (dir / "here").string();
  here.threads = 1;
  here.quiet = true;
  ASSERT_EQ(app::run_study(here), 0);
  ASSERT_TRUE(queue_empties_within(300)) << queue_and_node();

  // A run at a given thread count is bitwise reproducible: the numbers are the same, exactly.
  ASSERT_TRUE(fs::exists(out / "report" / "summary.json")) << "the report job wrote no report";
  EXPECT_EQ(measured(summary_of(out)), measured(summary_of(dir / "here")));
  for (const char* c : {"smooth", "rough"})
    EXPECT_TRUE(contains(read_text_file(out / "cases" / c / "run.log"), ", 1 thread\n")) << c;

  // The report job started after both array tasks had ended, and they completed.
  std::string last_task_end, report_start;
  int tasks = 0;
  for (const auto& job : finished_jobs()) {
    if (job.count("ArrayJobId") && job.at("ArrayJobId") == jobs.array) {
      ++tasks;
      EXPECT_EQ(job.at("JobState"), "COMPLETED") << job.at("JobId");
      last_task_end = std::max(last_task_end, job.at("EndTime"));  // ISO times order as text
    }
    if (job.at("JobId") == jobs.report) {
      report_start = job.at("StartTime");
      EXPECT_EQ(job.at("JobState"), "COMPLETED");
    }
  }
  EXPECT_EQ(tasks, 2);
  ASSERT_FALSE(report_start.empty()) << "the report job is not in the cluster's job record";
  EXPECT_GE(report_start, last_task_end);

  const ProcessResult status = trapdem_command({"study", file.string(), "--out", out.string(), "--status"});
  EXPECT_TRUE(contains(status.output, "2 runs: 2 finished")) << status.output;
  fs::remove_all(dir);
}

TEST_F(SlurmCluster, CancelledCaseResumesWhenTheStudyIsSubmittedAgain) {
  const fs::path dir = scratch("cancel");
  const fs::path file = write_file(dir / "study.toml", "name = \"slurm-one\"\n" + kScale + R"(trapdoor.travel = 0.004
output.snapshot_displacements = [0.0, 0.002, 0.004]
[report]
contours_at = 0.002
[cases.only]
label = "Only"
)");
  const fs::path out = dir / "out", run_dir = out / "cases" / "only";
  const std::vector<std::string> submit = {"study", file.string(), "--out", out.string(), "--submit", "slurm",
                                           "--cpus-per-task", "2"};
  ProcessResult submitted = trapdem_command(submit);
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output << submitted.errors;
  const SubmittedJobs first = jobs_printed(submitted.output);

  // Cancel the task mid-run: once its first stage has ended, long before the lowering does.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  while (!(fs::exists(run_dir / "run.log") && contains(read_text_file(run_dir / "run.log"), "stage pluviation finished")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(run_process({"scancel", first.array}).exit_code, 0);
  ASSERT_TRUE(queue_empties_within(120)) << queue_and_node();

  // SIGTERM from Slurm: the run wrote a checkpoint and stopped; --status reads it so.
  const std::string log = read_text_file(run_dir / "run.log");
  ASSERT_TRUE(contains(log, "stopped (checkpoint written")) << "the run was not stopped mid-run by scancel:\n" << log;
  EXPECT_TRUE(contains(log, ", 2 threads")) << "--cpus-per-task 2 should give the run 2 threads";
  EXPECT_TRUE(fs::exists(run_dir / "checkpoint.h5"));
  EXPECT_FALSE(run_finished(RunFolder(run_dir)));
  const ProcessResult stopped = trapdem_command({"study", file.string(), "--out", out.string(), "--status"});
  EXPECT_TRUE(contains(stopped.output, "only  stopped with a checkpoint at ")) << stopped.output;

  // Submitted again: the run resumes from its checkpoint and finishes; the report follows.
  submitted = trapdem_command(submit);
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output << submitted.errors;
  EXPECT_TRUE(contains(submitted.output, "(1 of 1 runs;")) << submitted.output;
  ASSERT_TRUE(queue_empties_within(300)) << queue_and_node();
  const std::string resumed = read_text_file(run_dir / "run.log");
  EXPECT_TRUE(contains(resumed, "trapdem run --resume " + run_dir.string())) << resumed;
  EXPECT_TRUE(std::regex_search(resumed, std::regex("resumed .* at t = .* \\(step [1-9][0-9]*, stage "))) << resumed;
  EXPECT_TRUE(run_finished(RunFolder(run_dir)));
  const Json cost = Json::parse(read_text_file(run_dir / "run.json"));
  EXPECT_EQ(cost["segments"].as_number(), 2.0);  // the cancelled segment and the resumed one
  const Json summary = summary_of(out);
  ASSERT_EQ(summary["cases"].size(), 1u);
  EXPECT_GT(summary["cases"][0]["min_load_ratio"].as_number(), 0.0);
  fs::remove_all(dir);
}

TEST_F(SlurmCluster, BadOptionsAreRefusedBeforeAnythingIsQueued) {
  const fs::path dir = scratch("bad");
  const fs::path file = write_file(dir / "study.toml", kStudy);
  const fs::path out = dir / "out";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--partition", "nope"}, "--partition 'nope': not a partition of this cluster (sinfo lists: debug)"},
      {{"--cpus-per-task", "0"}, "--cpus-per-task 0: expected a whole number from 1"},
      {{"--time", "25:61"}, "--time '25:61': seconds 61 is not below 60"},
      {{"--sbatch-arg=--array=1-9"}, "--sbatch-arg '--array=1-9': --array is set by trapdem itself"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args = {"study", file.string(), "--out", out.string(), "--submit", "slurm"};
    args.insert(args.end(), options.begin(), options.end());
    const ProcessResult r = trapdem_command(args);
    EXPECT_EQ(r.exit_code, 2) << options.front();
    EXPECT_TRUE(contains(r.errors, "trapdem: input error: " + message)) << r.errors;
    EXPECT_EQ(queue(), "") << options.front();
    EXPECT_FALSE(fs::exists(out)) << options.front() << ": the folder was written";
  }
  // A case that does not resolve: refused as a local study refuses it, before the array.
  const fs::path broken = write_file(dir / "broken.toml", kStudy + "[cases.rough.set.trapdoor]\nwidht = 0.05\n");
  const ProcessResult r =
      trapdem_command({"study", broken.string(), "--out", out.string(), "--submit", "slurm"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.errors, "case 'rough'")) << r.errors;
  EXPECT_EQ(queue(), "");
  EXPECT_FALSE(fs::exists(out / "slurm"));
  // The Slurm options without --submit are a command-line error.
  EXPECT_NE(trapdem_command({"study", file.string(), "--partition", "debug"}).exit_code, 0);
  fs::remove_all(dir);
}

TEST_F(SlurmCluster, CalibrationGridIsSubmittedAsAnArray) {
  const fs::path dir = scratch("calibrate");
  // A configuration file of the tiny preset's values; the target a PIV folder (not read before the ranking).
  const fs::path base = dir / "base.toml";
  fs::copy_file(fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml", base, fs::copy_options::overwrite_existing);
  fs::create_directories(dir / "piv");
  write_file(dir / "piv" / "piv.h5", "");
  const fs::path out = dir / "out";
  const std::vector<std::string> grid = {"calibrate", base.string(), "--vary", "contact.kinetic_friction=0.2,0.5",
                                         "--target", (dir / "piv").string(), "--at", "2mm", "--out", out.string()};
  std::vector<std::string> submit = grid;
  submit.insert(submit.end(), {"--submit", "slurm", "--time", "5:00", "--sbatch-arg=--hold"});
  const ProcessResult r = trapdem_command(submit);
  ASSERT_EQ(r.exit_code, 0) << r.output << r.errors;
  const SubmittedJobs jobs = jobs_printed(r.output);
  EXPECT_TRUE(contains(r.output, "(2 of 2 runs;")) << r.output;
  // Held (--hold passed through --sbatch-arg): both jobs wait in the queue, nothing runs.
  const std::string queued = queue();
  EXPECT_TRUE(contains(queued, jobs.report + " trapdem-calibrate-base-report PENDING")) << queued;
  const std::string array = read_text_file(out / "slurm" / "array.sbatch");
  EXPECT_EQ(run_process({"bash", "-n", (out / "slurm" / "array.sbatch").string()}).exit_code, 0);
  for (const char* c : {"kinetic_friction-0.2", "kinetic_friction-0.5"})
    EXPECT_TRUE(contains(array, "run_case " + (out / "cases" / c).string())) << array;
  EXPECT_TRUE(contains(array, "#SBATCH --hold\n"));
  EXPECT_TRUE(contains(array, "#SBATCH --time=5:00\n"));
  const std::string report = read_text_file(out / "slurm" / "report.sbatch");
  EXPECT_TRUE(contains(report, "  calibrate \\\n  " + base.string())) << report;
  EXPECT_TRUE(contains(report, "  --collect")) << report;
  std::vector<std::string> status = grid;
  status.push_back("--status");
  EXPECT_TRUE(contains(trapdem_command(status).output, "2 runs: 2 not started"));
  ASSERT_EQ(run_process({"scancel", jobs.array, jobs.report}).exit_code, 0);
  ASSERT_TRUE(queue_empties_within(60)) << queue_and_node();
  fs::remove_all(dir);
}
