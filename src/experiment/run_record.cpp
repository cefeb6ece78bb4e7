#include "experiment/run_record.hpp"

#include <cmath>
#include <exception>

#include <fmt/format.h>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/json.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"

namespace fs = std::filesystem;

namespace trapdem {

void RunHistory::store(std::map<std::string, std::string>& metadata, double seconds_in_segment) const {
  // The shortest text that reads back as the same double: a resume adds to it again.
  metadata[kWallSeconds] = fmt::format("{}", wall_seconds + seconds_in_segment);
  metadata[kSegments] = fmt::format("{}", segments);
}

std::optional<RunHistory> RunHistory::from(const std::map<std::string, std::string>& metadata) {
  const auto wall = metadata.find(kWallSeconds), segments = metadata.find(kSegments);
  if (wall == metadata.end() || segments == metadata.end()) return std::nullopt;
  auto read = [](const auto& entry, const char* expected) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(entry->second, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != entry->second.size() || !std::isfinite(v) || v < 0.0)
      throw InputError(fmt::format("checkpoint metadata {} = '{}': expected {}", entry->first, entry->second, expected));
    return v;
  };
  RunHistory h;
  h.wall_seconds = read(wall, "a wall clock time >= 0 s");
  h.segments = read(segments, "a count of segments >= 0") + 1.0;  // the segment that wrote it is done
  return h;
}

RunHistory RunHistory::from_record(const RunFolder& folder) {
  const fs::path file = folder.run_json();
  RunHistory h;
  if (!fs::exists(file)) return h;
  try {
    const Json previous = Json::parse(read_text_file(file), file.string());
    h.wall_seconds = previous["wall_seconds"].as_number();
    h.segments = previous["segments"].as_number();
  } catch (const InputError&) {
    return RunHistory{};  // an unreadable record (another version's) restarts the count; the results stand
  }
  return h;
}

double record_run_segment(const RunFolder& folder, const RunSegment& s, const RunHistory& history) {
  const double total_seconds = history.wall_seconds + s.seconds;
  Json j = Json::object();
  j.set("complete", s.complete);
  j.set("stage", s.stage);
  j.set("segments", history.segments + 1.0);
  j.set("wall_seconds", total_seconds);
  j.set("steps", double(s.steps));
  j.set("particle_steps", s.particle_steps);
  j.set("particles", s.particles);
  const double per_second = total_seconds > 0.0 ? s.particle_steps / total_seconds : 0.0;
  j.set("particle_steps_per_second", per_second);
  // This segment's code and host (an earlier segment's are in run.log's header lines).
  const BuildInfo& build = build_info();
  j.set("trapdem_commit", std::string(build.commit));
  j.set("trapdem_modified", build.modified);
  j.set("cpu", describe_cpu());
  j.set("threads", s.threads);
  j.set("ranks", s.ranks);
  write_text_atomically(folder.run_json(), j.dump() + "\n");
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
