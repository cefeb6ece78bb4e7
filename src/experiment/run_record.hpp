#pragma once
// run.json: a run's work so far, over all its segments (a first run and each --resume). A segment
// ended by a kill counts up to its last checkpoint: every checkpoint carries the run's wall clock
// and segments so far (RunHistory), and a resume counts on from there. Studies read run.json to
// know whether a case finished and what it cost; issue 12's paper-scale timing is its wall clock.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "experiment/run_folder.hpp"

namespace trapdem {

struct RunSegment {
  bool complete = false;       // the run reached its end in this segment
  std::string stage;           // the stage it ended in
  double seconds = 0.0;        // wall clock of the segment
  std::int64_t steps = 0;      // engine steps of the run since its start (the engine's count)
  double particle_steps = 0.0; // particle-steps of the run since its start (the experiment's count)
  std::size_t particles = 0;   // at the segment's end
  int threads = 1;             // OpenMP threads (per rank)
  int ranks = 1;               // MPI ranks
};

// The run's wall clock and segments before the current segment. Counted to the checkpoint a
// resume starts from, a killed segment's work is in the total; the time between its last
// checkpoint and the kill is not (at most output.checkpoint_interval, redone and counted in the
// next segment).
struct RunHistory {
  double wall_seconds = 0.0;
  double segments = 0.0;  // segments before this one, a killed one included

  static constexpr const char* kWallSeconds = "run.wall_seconds";
  static constexpr const char* kSegments = "run.segments";
  // Into a checkpoint's metadata, `seconds_in_segment` into the segment after this history.
  void store(std::map<std::string, std::string>& metadata, double seconds_in_segment) const;
  // The history a checkpoint stored (its segment then counts as done); none in a checkpoint of an
  // older trapdem. Throws InputError naming the key for a value that is not a count or a time.
  static std::optional<RunHistory> from(const std::map<std::string, std::string>& metadata);
  // For such an older checkpoint: the folder's run.json totals (the segments that ended with a
  // checkpoint); zero if it is missing or unreadable (another version's record).
  static RunHistory from_record(const RunFolder& folder);
};

// Writes the folder's run.json (atomically): the history plus the segment, with the code and the
// host of the segment (its commit, the CPU, threads and ranks: what a timing or a result is traced
// to; a run resumed by another build says so in run.log, each segment's header). Returns the
// particle-steps per second it records (the run's work over its wall clock, all segments), for
// the run's last line.
double record_run_segment(const RunFolder& folder, const RunSegment& segment, const RunHistory& history = {});

// Whether run.json says the run finished (false if it is missing or unreadable: a resume then
// finishes at once if the run had).
bool run_finished(const RunFolder& folder);

}  // namespace trapdem
