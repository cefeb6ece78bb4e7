// The whole run's progress line: its arithmetic as plain functions (work ahead, the run's percent
// across stage changes, the ETA from a sliding-window rate), its text, and a tiny run's lines.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/json.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/run_progress.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/text_file.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;
using trapdem::test::ScratchDir;

namespace {

// dt = 1 ms; the pour planned at 1 s, settling at most 2 s, spin-up at most 3 s, lowering 1 s.
StagePlan plan() {
  StagePlan p;
  p.time_step = 1e-3;
  p.pour_seconds = 1.0;
  p.settling_max = 2.0;
  p.spin_up_max = 3.0;
  p.travel = 0.1;
  p.rate = 0.1;
  return p;
}

}  // namespace

TEST(RunProgress, WorkAheadIsParticlesTimesStepsPerStage) {
  RunPosition start;
  start.final_particles = 100;
  // Pour: the count grows from 0 to 100 over 1000 steps (mean 50); then 100 x 2000, 100 x 3000, 100 x 1000.
  EXPECT_DOUBLE_EQ(work_ahead(plan(), start), 1000 * 50.0 + 100 * 2000.0 + 100 * 3000.0 + 100 * 1000.0);
  RunPosition settling;
  settling.stage = 1;
  settling.particles = settling.final_particles = 100;
  settling.stage_steps = 500;
  EXPECT_DOUBLE_EQ(work_ahead(plan(), settling), 100 * 1500.0 + 100 * 3000.0 + 100 * 1000.0);
  settling.stage_steps = 5000;  // past max_time (cannot happen): nothing left of the stage, not negative
  EXPECT_DOUBLE_EQ(work_ahead(plan(), settling), 100 * 3000.0 + 100 * 1000.0);
  RunPosition lowering;
  lowering.stage = 3;
  lowering.particles = lowering.final_particles = 100;
  lowering.travel_done = 0.025;
  EXPECT_NEAR(work_ahead(plan(), lowering), 100 * 750.0, 1e-6);
  lowering.stage = 4;
  EXPECT_EQ(work_ahead(plan(), lowering), 0.0);
  // Once 5 % is poured the pour's steps left come from its pace: 20 % in 400 steps -> 1600 more.
  RunPosition pour;
  pour.particles = 20;
  pour.final_particles = 100;
  pour.pour_fraction = 0.2;
  pour.stage_steps = 400;
  EXPECT_DOUBLE_EQ(work_ahead(plan(), pour), 1600 * 60.0 + 100 * 6000.0);
}

// A made-up run: the pour, settling that ends at a quarter of its max_time, spin-up, lowering;
// the percent never goes back, jumps ahead when settling ends early, and reaches 100 %.
TEST(RunProgress, PercentMonotonicAcrossStageChanges) {
  RunFraction fraction;
  double done = 0.0, last = 0.0;
  int jumps = 0;
  auto check = [&](const RunPosition& at) {
    const double f = fraction.update(done, work_ahead(plan(), at));
    EXPECT_GE(f, last) << "stage " << at.stage << " step " << at.stage_steps;
    if (f > last + 0.05) ++jumps;
    last = f;
  };
  RunPosition at;
  at.final_particles = 100;
  for (int s = 0; s <= 1200; s += 100) {  // the pour takes 1200 steps, not the 1000 planned
    at.stage_steps = s;
    at.pour_fraction = s / 1200.0;
    at.particles = 100.0 * at.pour_fraction;
    check(at);
    done += 100 * at.particles;
  }
  for (int stage : {1, 2, 3}) {
    at.stage = stage;
    at.particles = 100;
    const int steps = stage == 1 ? 500 : stage == 2 ? 3000 : 1000;  // settling ends early
    for (int s = 0; s <= steps; s += 100) {
      at.stage_steps = s;
      at.travel_done = stage == 3 ? 0.1 * s / 1000.0 : 0.0;
      check(at);
      if (s < steps) done += 100 * 100.0;
    }
  }
  at.stage = 4;
  check(at);
  EXPECT_DOUBLE_EQ(last, 1.0);
  EXPECT_EQ(jumps, 1);  // settling's unused 1500 steps, once
  // An estimate that grows (the count passes the one expected) holds the percent, never lowers it.
  RunFraction held;
  const double before = held.update(500.0, 500.0);
  EXPECT_DOUBLE_EQ(held.update(510.0, 1500.0), before);
}

TEST(RunProgress, EtaFromTheRateOverASlidingWindow) {
  WorkRate rate(60.0);
  EXPECT_FALSE(rate.known());
  rate.add(0.0, 0.0);
  EXPECT_FALSE(rate.known());  // one sample: no rate yet ("left estimating")
  for (int t = 10; t <= 100; t += 10) rate.add(t, 1e5 * t);
  ASSERT_TRUE(rate.known());
  EXPECT_DOUBLE_EQ(rate.per_second(), 1e5);
  EXPECT_DOUBLE_EQ(5e6 / rate.per_second(), 50.0);  // the ETA of 5e6 particle-steps ahead
  // The machine gets twice as fast: one window later the rate is the new one alone.
  double work = 1e7;
  for (int t = 110; t <= 170; t += 10) rate.add(t, work += 2e6);
  EXPECT_DOUBLE_EQ(rate.per_second(), 2e5);
  // At a steady rate the ETA of a run whose work ahead shrinks (with a stage ending early) never grows.
  WorkRate steady(60.0);
  double done = 0.0, eta_before = 1e300;
  const double total = 3e7;
  for (int t = 0; t <= 200; t += 5) {
    steady.add(t, done);
    double ahead = total - done;
    if (t >= 100) ahead = std::max(0.0, ahead - 5e6);  // a stage ended before its bound
    if (steady.known()) {
      const double eta = ahead / steady.per_second();
      EXPECT_LE(eta, eta_before + 1e-9) << "at " << t << " s";
      eta_before = eta;
    }
    done += 5 * 1e5;
  }
}

TEST(RunProgress, Text) {
  EXPECT_EQ(fixed_text(-0.0, 2), "0.00");
  EXPECT_EQ(fixed_text(-1e-12, 2), "0.00");
  EXPECT_EQ(fixed_text(-0.004, 2), "0.00");
  EXPECT_EQ(fixed_text(-0.006, 2), "-0.01");
  EXPECT_EQ(fixed_text(1.0, 2), "1.00");
  EXPECT_EQ(threads_text(1), "1 thread");
  EXPECT_EQ(threads_text(2), "2 threads");
  EXPECT_EQ(format_duration(-1.0), "estimating");
  EXPECT_EQ(format_duration(42.0), "42 s");
  EXPECT_EQ(format_duration(300.0), "5.0 min");
  EXPECT_EQ(format_duration(9000.0), "2.5 h");

  StageProgress p;
  p.stage = Stage::settling;
  p.run_fraction = 0.372;
  p.seconds_left = 192.0;
  p.fraction = 0.45;
  p.simulated_time = 0.1234;
  p.particle_steps_per_second = 1.234e6;
  p.detail = "kinetic/potential energy 1.2e-04";
  EXPECT_EQ(progress_line(p), "stage 2 of 4 (settling)   run  37.2%  left 3.2 min    | stage  45.0%  t = 0.1234 s  "
                              "1.23 M particle-steps/s  kinetic/potential energy 1.2e-04");
  p.stage = Stage::pluviation;
  p.seconds_left = -1.0;
  p.particle_steps_per_second = 0.0;
  p.detail.clear();
  EXPECT_EQ(progress_line(p), "stage 1 of 4 (pluviation) run  37.2%  left estimating | stage  45.0%  t = 0.1234 s");
}

// A tiny run's run.log (the terminal's lines): one line per report, each "stage k of 4", the run's
// percent never going back, no "?" and no "-0.00"; "1 thread"; the summary once, with run.json's rate.
TEST(RunProgress, TinyRunPrintedLines) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-progress");
  const fs::path out = scratch / "run";
  FolderRunOptions o;
  o.config_file = fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml";
  o.overrides = {"pluviation.fill_height=0.01", "settling.max_time=0.01", "spin_up.ramp_time=0.005",
                 "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]", "output.log_interval=0.001"};
  o.out_dir = out;
  o.quiet = true;
  o.threads = 1;
  ASSERT_TRUE(run_in_folder(o));
  std::istringstream log(read_text_file(out / "run.log"));
  const std::regex progress(R"(^stage ([1-4]) of 4 \((pluviation|settling|spin-up|lowering)\) +run +([0-9.]+)%  left (.+?) +\| stage +[0-9.]+%  t = .*)");
  std::string line, finished;
  double last = -1.0;
  int last_stage = 0, lines = 0, finished_lines = 0;
  bool thread_line = false;
  while (std::getline(log, line)) {
    EXPECT_EQ(line.find("-0.00"), std::string::npos) << line;
    EXPECT_EQ(line.find(" ?"), std::string::npos) << line;
    if (line.find(", 1 thread") != std::string::npos && line.find("1 threads") == std::string::npos) thread_line = true;
    if (line.rfind("finished after", 0) == 0) {
      ++finished_lines;
      finished = line;
    }
    std::smatch m;
    if (!std::regex_match(line, m, progress)) continue;
    ++lines;
    const int stage = std::stoi(m[1]);
    const double percent = std::stod(m[3]);
    EXPECT_GE(stage, last_stage) << line;
    EXPECT_GE(percent, last) << line;
    last_stage = stage;
    last = percent;
  }
  EXPECT_GE(lines, 8);
  EXPECT_EQ(last_stage, 4);
  EXPECT_TRUE(thread_line);
  ASSERT_EQ(finished_lines, 1);
  const Json record = Json::parse(read_text_file(out / "run.json"), "run.json");
  EXPECT_NE(finished.find(fmt::format("{:.2f} M particle-steps/s", record["particle_steps_per_second"].as_number() / 1e6)),
            std::string::npos) << finished;
}
