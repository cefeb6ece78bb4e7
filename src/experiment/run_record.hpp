#pragma once
// run.json: a run's work so far, summed over its segments (a first run and each --resume that
// ended, finished or stopped); a segment ended by a kill is not counted. Studies read it to know
// whether a case finished and what it cost.
#include <cstddef>
#include <cstdint>
#include <string>

#include "experiment/run_folder.hpp"

namespace trapdem {

struct RunSegment {
  bool complete = false;      // the run reached its end in this segment
  std::string stage;          // the stage it ended in
  double seconds = 0.0;       // wall clock of the segment
  std::int64_t steps = 0;     // engine steps of the segment
  double particle_steps = 0.0;
  std::size_t particles = 0;  // at the segment's end
};

// Adds the segment to the folder's run.json (written atomically). An unreadable record (written by
// another version) restarts the count: the run's results stand. Returns the particle-steps per
// second it records (the run's work over its wall clock, all segments), for the run's last line.
double record_run_segment(const RunFolder& folder, const RunSegment& segment);

// Whether run.json says the run finished (false if it is missing or unreadable: a resume then
// finishes at once if the run had).
bool run_finished(const RunFolder& folder);

}  // namespace trapdem
