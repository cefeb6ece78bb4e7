// Issue 14, "resume": a resumed run is the run that was started. The checkpoint stores the whole
// resolved configuration; a resume that would run another one (an edited resolved.toml, a --set,
// another file) is refused naming the first differing key unless --allow-change names it. A kill
// right after the stage-end checkpoint no longer duplicates the lowering's first snapshot; a folder
// stopped before its first checkpoint restarts with --resume; checkpoints are taken inside a stage;
// a folder another process is running is refused; a killed segment counts in run.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "../io/io_test_support.hpp"
#include "core/errors.hpp"
#include "core/json.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/run_record.hpp"
#include "experiment/run_identity.hpp"
#include "experiment/run_recorder.hpp"
#include "io/checkpoint.hpp"
#include "io/folder_lock.hpp"
#include "io/snapshot.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;
using io_testing::read_all;
using io_testing::ScratchDir;

const fs::path kTiny = fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml";

// The tiny preset made smaller still: ~240 particles, every stage short (about 68 000 steps).
const std::vector<std::string> kSmall = {
    "pluviation.fill_height=0.012", "pluviation.drop_height=0.01", "settling.max_time=0.01",
    "settling.min_time=0.002",      "spin_up.ramp_time=0.004",      "trapdoor.travel=0.0012",
    "output.snapshot_displacements=[0.0, 0.001]"};

FolderRunOptions fresh(const fs::path& out, std::int64_t stop_at_step = 0) {
  FolderRunOptions o;
  o.config_file = kTiny;
  o.overrides = kSmall;
  o.out_dir = out;
  o.quiet = true;
  o.threads = 1;  // bitwise repeatable
  o.stop_at_step = stop_at_step;
  return o;
}

FolderRunOptions resume(const fs::path& dir, std::int64_t stop_at_step = 0) {
  FolderRunOptions o;
  o.resume_dir = dir;
  o.quiet = true;
  o.threads = 1;
  o.stop_at_step = stop_at_step;
  return o;
}

std::string refusal(const FolderRunOptions& o) {
  try {
    run_in_folder(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResumeIdentity, AChangedConfigurationIsRefusedUnlessAllowed) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));

  FolderRunOptions with_set = resume(run, 400);
  with_set.overrides = {"trapdoor.rate=0.2"};
  std::string m = refusal(with_set);
  EXPECT_NE(m.find("--allow-change trapdoor.rate"), std::string::npos) << m;

  FolderRunOptions with_file = resume(run, 400);
  with_file.config_file = kTiny;
  m = refusal(with_file);
  EXPECT_NE(m.find("give no configuration file or --preset"), std::string::npos) << m;

  FolderRunOptions not_resuming = fresh(dir / "other", 400);
  not_resuming.allowed_changes = {"trapdoor.rate"};
  EXPECT_NE(refusal(not_resuming).find("only with --resume"), std::string::npos);

  // resolved.toml edited after the run started.
  const std::string resolved = read_all(run / "resolved.toml");
  std::string edited = resolved;
  ASSERT_NE(edited.find("\nrate = 0.1 "), std::string::npos) << resolved;
  edited.replace(edited.find("\nrate = 0.1 "), 11, "\nrate = 0.2 ");
  std::ofstream(run / "resolved.toml") << edited;
  m = refusal(resume(run, 400));
  EXPECT_NE(m.find("trapdoor.rate was 0.1 at the checkpoint, is 0.2 now"), std::string::npos) << m;
  EXPECT_NE(m.find("--allow-change trapdoor.rate"), std::string::npos) << m;
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 300);  // nothing ran

  // A misspelt --allow-change key is refused, naming it and the key meant (issue 41).
  FolderRunOptions misspelt = resume(run, 400);
  misspelt.allowed_changes = {"trapdoor.rat"};
  m = refusal(misspelt);
  EXPECT_NE(m.find("--allow-change trapdoor.rat: not a key of this run's configuration (did you mean trapdoor.rate?)"),
            std::string::npos) << m;
  misspelt.allowed_changes = {"nosuch.key"};
  m = refusal(misspelt);
  EXPECT_NE(m.find("--allow-change nosuch.key: not a key of this run's configuration"), std::string::npos) << m;
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 300);  // nothing ran

  // Allowed: it runs, and the change is in run.log, resolved.toml and the next checkpoint.
  FolderRunOptions allowed = resume(run, 400);
  allowed.allowed_changes = {"trapdoor.rate"};
  EXPECT_FALSE(run_in_folder(allowed));
  EXPECT_NE(read_all(run / "run.log").find("changed on resume at step 300 (--allow-change): trapdoor.rate = 0.2 (was "
                                           "0.1)"),
            std::string::npos);
  EXPECT_EQ(read_all(run / "resolved.toml").rfind("# changed on resume at step 300 (--allow-change): trapdoor.rate", 0),
            0u);
  const Checkpoint c = read_checkpoint(run / "checkpoint.h5");
  EXPECT_EQ(c.stats.steps, 400);
  EXPECT_NE(c.metadata.at(RunRecorder::kConfiguration).find("\nrate = 0.2"), std::string::npos);
  // The same configuration resumes without a word.
  EXPECT_FALSE(run_in_folder(resume(run, 500)));
}

// A checkpoint written before the configuration was stored in it (an older trapdem): nothing to
// compare, so the resume goes on with resolved.toml as it is, and says so in run.log.
TEST(ResumeIdentity, ACheckpointWithoutAStoredConfigurationResumesWithANote) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));
  Checkpoint old = read_checkpoint(run / "checkpoint.h5");
  ASSERT_EQ(old.metadata.erase(RunRecorder::kConfiguration), 1u);
  old.metadata.erase(RunRecorder::kConfigurationDigest);
  write_checkpoint(run / "checkpoint.h5", old);
  EXPECT_FALSE(run_in_folder(resume(run, 400)));
  EXPECT_NE(read_all(run / "run.log").find("note: the checkpoint was written by an older trapdem and holds no "
                                           "configuration; resolved.toml is taken as it is"),
            std::string::npos);
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 400);
}

// A checkpoint written by an older trapdem, before a key existed: its stored configuration lacks
// the key. Read again by this trapdem the key comes in at its default, which is the old behaviour:
// the run resumes. Where the run now holds another value of it, or the stored text holds a key this
// trapdem no longer reads, the resume is refused naming that key.
TEST(ResumeIdentity, AKeyAddedSinceTheCheckpointResumesAtItsDefault) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));
  const Checkpoint written = read_checkpoint(run / "checkpoint.h5");
  auto with_stored_configuration = [&](const std::string& from, const std::string& to) {
    Checkpoint c = written;
    std::string& text = c.metadata.at(RunRecorder::kConfiguration);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << text;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    c.metadata.at(RunRecorder::kConfigurationDigest) = config_digest(text);  // as the older trapdem wrote it
    write_checkpoint(run / "checkpoint.h5", c);
  };

  // numerics.max_overlap_fraction at its default (0.25) in this run, absent from the checkpoint.
  with_stored_configuration("\nmax_overlap_fraction = 0.25\n", "\n");
  EXPECT_FALSE(run_in_folder(resume(run, 400)));
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 400);
  EXPECT_EQ(read_all(run / "run.log").find("changed on resume"), std::string::npos);

  // Absent from a checkpoint, while the run now holds another value: refused, named.
  const std::string resolved = read_all(run / "resolved.toml"), at_default = "\nmax_overlap_fraction = 0.25\n";
  std::string edited = resolved;
  ASSERT_NE(edited.find(at_default), std::string::npos) << resolved;
  edited.replace(edited.find(at_default), at_default.size(), "\nmax_overlap_fraction = 0.3\n");
  std::ofstream(run / "resolved.toml") << edited;
  with_stored_configuration("\nmax_overlap_fraction = 0.25\n", "\n");
  std::string m = refusal(resume(run, 500));
  EXPECT_NE(m.find("numerics.max_overlap_fraction was 0.25 at the checkpoint, is 0.3 now"), std::string::npos) << m;
  std::ofstream(run / "resolved.toml") << resolved;

  // A key this trapdem does not read (retired since) in the checkpoint: named as a change.
  with_stored_configuration("\n[numerics]\n", "\n[numerics]\nretired_key = 1\n");
  m = refusal(resume(run, 500));
  EXPECT_NE(m.find("numerics.retired_key was 1 at the checkpoint, is (absent) now"), std::string::npos) << m;
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 300);  // nothing ran
}

// The kill of issue 14: the stage-end checkpoint at the end of spin-up (step N), then the lowering's
// first snapshot at the same step N, then a kill before the next checkpoint. The resume must not
// write that snapshot a second time, and ends as a run that went straight through.
TEST(ResumeIdentity, AKillAfterTheStageEndCheckpointDuplicatesNoSnapshot) {
  ScratchDir dir;
  const fs::path straight = dir / "straight";
  ASSERT_TRUE(run_in_folder(fresh(straight)));
  const auto expected = list_snapshots(straight / "snapshots.h5");
  ASSERT_EQ(expected.size(), 5u);
  ASSERT_EQ(expected[2].stage, "lowering");
  const std::int64_t n = expected[2].step;  // the lowering starts: checkpoint, then this snapshot

  const fs::path killed = dir / "killed";
  ASSERT_FALSE(run_in_folder(fresh(killed, n)));
  EXPECT_EQ(read_checkpoint(killed / "checkpoint.h5").stats.steps, n);
  fs::copy_file(killed / "checkpoint.h5", dir / "checkpoint-at-n.h5");
  ASSERT_FALSE(run_in_folder(resume(killed, n + 300)));  // writes the snapshot at n, a checkpoint at n + 300
  ASSERT_EQ(list_snapshots(killed / "snapshots.h5").size(), 3u);
  fs::copy_file(dir / "checkpoint-at-n.h5", killed / "checkpoint.h5", fs::copy_options::overwrite_existing);

  ASSERT_TRUE(run_in_folder(resume(killed)));
  const auto got = list_snapshots(killed / "snapshots.h5");
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].step, expected[i].step) << i;
    EXPECT_EQ(got[i].stage, expected[i].stage) << i;
  }
  EXPECT_EQ(read_all(killed / "trapdoor.csv"), read_all(straight / "trapdoor.csv"));
  // The XDMF companion names the file that exists; no file of the rewrite is left.
  EXPECT_FALSE(fs::exists(killed / ".resume-snapshots.xmf"));
  EXPECT_FALSE(fs::exists(killed / ".resume-snapshots.h5"));
  const std::string xmf = read_all(killed / "snapshots.xmf");
  EXPECT_EQ(xmf.find(".resume-"), std::string::npos);
  EXPECT_NE(xmf.find("snapshots.h5:"), std::string::npos);
}

TEST(ResumeIdentity, AFolderWithoutACheckpointRestartsFromTheBeginning) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));
  // Killed while writing its first checkpoint: no checkpoint.h5, and run.log without the note that
  // RunRecorder writes once one is complete.
  fs::remove(run / "checkpoint.h5");
  std::string log_text = read_all(run / "run.log");
  ASSERT_NE(log_text.find("\ncheckpoint at t = "), std::string::npos) << log_text;
  log_text.erase(log_text.find("\ncheckpoint at t = ") + 1);
  std::ofstream(run / "run.log", std::ios::trunc) << log_text;
  std::ofstream(run / ".checkpoint.h5.tmp-1-1") << "partial";
  std::ofstream(run / ".snapshots.h5.tmp-1-2") << "partial";
  fs::create_directories(run / "snapshots");
  std::ofstream(run / "snapshots" / ".000003.h5.tmp-1-3") << "partial";
  // --resume is the one command for such a folder (a fresh run into it would mix two logs).
  EXPECT_FALSE(run_in_folder(resume(run, 300)));
  // The interrupted writes' temporaries are gone (issue 41), and run.log says so.
  EXPECT_FALSE(fs::exists(run / ".checkpoint.h5.tmp-1-1"));
  EXPECT_FALSE(fs::exists(run / ".snapshots.h5.tmp-1-2"));
  EXPECT_FALSE(fs::exists(run / "snapshots" / ".000003.h5.tmp-1-3"));
  EXPECT_NE(read_all(run / "run.log").find("removed 3 temporary files of a write the stop interrupted"),
            std::string::npos);
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 300);
  EXPECT_NE(read_all(run / "run.log").find("the run stopped before its first checkpoint was complete): starting it again "
                                           "from the beginning"),
            std::string::npos);

  // checkpoint.h5 deleted after checkpoints were complete (run.log records them): said so, not
  // "stopped before its first checkpoint", and on stderr under --quiet too (issue 41).
  fs::remove(run / "checkpoint.h5");
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE(run_in_folder(resume(run, 300)));  // resume() is quiet
  const std::string said = ::testing::internal::GetCapturedStderr();
  const std::string truth = "checkpoint.h5 is missing from " + run.string() +
                            ", although run.log records 1 completed checkpoint (the last at step 300): it was "
                            "deleted or moved; starting the run again from the beginning";
  EXPECT_NE(said.find(truth), std::string::npos) << said;
  EXPECT_NE(read_all(run / "run.log").find(truth), std::string::npos);
  // A folder with neither is no run folder.
  fs::create_directories(dir / "empty");
  EXPECT_NE(refusal(resume(dir / "empty")).find("not a run folder"), std::string::npos);
}

// A folder another process is running (its run.lock held) is refused, by a resume and by a fresh
// run with the same --out, before anything in it is written; once that process is gone the run
// carries on as if nothing had happened.
TEST(ResumeIdentity, AFolderInUseByAnotherProcessIsRefusedUntouched) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));
  const std::string log_before = read_all(run / "run.log");
  const std::string checkpoint_before = read_all(run / "checkpoint.h5");
  {
    FolderLock other(run / "run.lock", "unused");  // as the other process holds it
    const std::string m = refusal(resume(run, 400));
    EXPECT_NE(m.find(run.string() + " is in use by another trapdem process (pid "), std::string::npos) << m;
    EXPECT_NE(m.find("wait until it ends"), std::string::npos) << m;
    EXPECT_EQ(read_all(run / "run.log"), log_before);
    EXPECT_EQ(read_all(run / "checkpoint.h5"), checkpoint_before);

    // A fresh run into a folder whose run has not yet written its first checkpoint (only run.log
    // and resolved.toml exist for the first half hour of a real run).
    const fs::path starting = dir / "starting";
    fs::create_directories(starting);
    FolderLock starting_lock(starting / "run.lock", "unused");
    const std::string m2 = refusal(fresh(starting, 400));
    EXPECT_NE(m2.find(starting.string() + " is in use by another trapdem process"), std::string::npos) << m2;
    EXPECT_FALSE(fs::exists(starting / "run.log"));
    EXPECT_FALSE(fs::exists(starting / "resolved.toml"));
  }
  EXPECT_FALSE(run_in_folder(resume(run, 400)));
  EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").stats.steps, 400);
}

// run.json counts a segment ended by a kill up to its last checkpoint (issue 12 times a paper-scale
// run from run.json, and a session's end kills it): each checkpoint carries the run's wall clock and
// segments, and the resume counts on from there. The steps and particle-steps are then the run's
// own, equal to those of a run that went straight through.
TEST(ResumeIdentity, AKilledSegmentCountsUpToItsLastCheckpoint) {
  ScratchDir dir;
  const fs::path run = dir / "run";
  ASSERT_FALSE(run_in_folder(fresh(run, 300)));  // segment 1 stops cleanly
  const std::string record_after_first = read_all(run / "run.json");
  ASSERT_FALSE(run_in_folder(resume(run, 400)));  // segment 2: its checkpoint at 400, then ...
  const Checkpoint at_400 = read_checkpoint(run / "checkpoint.h5");
  const std::optional<RunHistory> stored = RunHistory::from(at_400.metadata);
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->segments, 2.0);
  std::ofstream(run / "run.json") << record_after_first;  // ... a kill before its run.json was written
  ASSERT_FALSE(run_in_folder(resume(run, 500)));
  const Json record = Json::parse(read_all(run / "run.json"), "run.json");
  EXPECT_EQ(record["segments"].as_number(), 3.0);
  EXPECT_EQ(record["steps"].as_number(), 500.0);
  EXPECT_GE(record["wall_seconds"].as_number(), stored->wall_seconds);

  ASSERT_FALSE(run_in_folder(fresh(dir / "straight", 500)));
  const Json straight = Json::parse(read_all(dir / "straight" / "run.json"), "run.json");
  EXPECT_EQ(record["particle_steps"].as_number(), straight["particle_steps"].as_number());
  EXPECT_EQ(straight["segments"].as_number(), 1.0);
  EXPECT_EQ(straight["steps"].as_number(), 500.0);
}

TEST(ResumeIdentity, ABadRunHistoryInACheckpointIsAClearError) {
  EXPECT_FALSE(RunHistory::from({{"run.name", "x"}}));  // an older trapdem's checkpoint
  for (const char* bad_text : {"", "abc", "-1", "inf", "nan", "12s"}) {
    const std::string bad = bad_text;
    try {
      RunHistory::from({{RunHistory::kWallSeconds, bad}, {RunHistory::kSegments, "0"}});
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("checkpoint metadata run.wall_seconds = '" + bad + "'"), std::string::npos)
          << e.what();
    }
  }
  const std::optional<RunHistory> h = RunHistory::from({{RunHistory::kWallSeconds, "12.5"}, {RunHistory::kSegments, "1"}});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->wall_seconds, 12.5);
  EXPECT_EQ(h->segments, 2.0);
}

// With a short interval, checkpoints come every 256 steps inside a stage (the pour here), not only
// at stage ends: a kill loses at most one interval (and those 256 steps).
TEST(ResumeIdentity, CheckpointsAreTakenInsideALongStage) {
  ScratchDir dir;
  FolderRunOptions o = fresh(dir / "run", 4000);
  o.overrides.push_back("output.checkpoint_interval=1e-9");
  ASSERT_FALSE(run_in_folder(o));
  const std::string log = read_all(dir / "run" / "run.log");
  const std::regex line(R"(checkpoint at t = [0-9.]+ s \(step ([0-9]+), stage pluviation\))");
  std::vector<long> steps;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator(); ++it)
    steps.push_back(std::stol((*it)[1]));
  ASSERT_GE(steps.size(), 15u) << log;
  EXPECT_LE(steps.front(), 256);
  for (std::size_t i = 1; i < steps.size(); ++i) EXPECT_LE(steps[i] - steps[i - 1], 256) << i;
  EXPECT_EQ(steps.back(), 4000);  // the stop's own
}

}  // namespace
}  // namespace trapdem
