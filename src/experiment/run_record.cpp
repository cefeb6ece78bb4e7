#include "experiment/run_record.hpp"

#include "core/errors.hpp"
#include "core/json.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"

namespace fs = std::filesystem;

namespace trapdem {

double record_run_segment(const RunFolder& folder, const RunSegment& s) {
  const fs::path file = folder.run_json();
  double total_seconds = s.seconds, total_particle_steps = s.particle_steps;
  double total_steps = double(s.steps), segments = 1.0;
  if (fs::exists(file)) {
    try {
      const Json previous = Json::parse(read_text_file(file), file.string());
      total_seconds += previous["wall_seconds"].as_number();
      total_steps += previous["steps"].as_number();
      total_particle_steps += previous["particle_steps"].as_number();
      segments += previous["segments"].as_number();
    } catch (const InputError&) {
      // An unreadable record (written by another version) restarts the count: the run's results stand.
    }
  }
  Json j = Json::object();
  j.set("complete", s.complete);
  j.set("stage", s.stage);
  j.set("segments", segments);
  j.set("wall_seconds", total_seconds);
  j.set("steps", total_steps);
  j.set("particle_steps", total_particle_steps);
  j.set("particles", s.particles);
  const double per_second = total_seconds > 0.0 ? total_particle_steps / total_seconds : 0.0;
  j.set("particle_steps_per_second", per_second);
  write_text_atomically(file, j.dump() + "\n");
  return per_second;
}

bool run_finished(const RunFolder& folder) {
  const fs::path record = folder.run_json();
  if (!fs::exists(record)) return false;
  try {
    const Json j = Json::parse(read_text_file(record), record.string());
    return j.contains("complete") && j["complete"].as_bool();
  } catch (const InputError&) {
    return false;  // an unreadable record: resume, which finishes at once if the run had
  }
}

}  // namespace trapdem
