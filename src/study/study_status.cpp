#include "study/study_status.hpp"

#include <chrono>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "experiment/run_folder.hpp"
#include "experiment/run_record.hpp"
#include "io/text_file.hpp"
#include "study/study_runner.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// The run log lines that decide a state, as run_in_folder writes them (experiment/folder_run.cpp).
constexpr const char* kErrorLine = "stopped by an error:";
constexpr const char* kStopLine = "stopped (checkpoint written";

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string format_age(double seconds) {
  if (seconds < 120.0) return fmt::format("{:.0f} s", seconds);
  if (seconds < 7200.0) return fmt::format("{:.0f} min", seconds / 60.0);
  return fmt::format("{:.1f} h", seconds / 3600.0);
}

}  // namespace

std::string to_string(RunState s) {
  switch (s) {
    case RunState::not_started: return "not started";
    case RunState::running: return "running";
    case RunState::stopped: return "stopped";
    case RunState::finished: return "finished";
    case RunState::failed: return "failed";
  }
  return "?";
}

RunStatus run_status(const fs::path& dir) {
  RunStatus s;
  s.dir = dir;
  const RunFolder folder(dir);
  if (run_finished(folder)) {
    s.state = RunState::finished;
    return s;
  }
  const fs::path log = folder.run_log();
  if (!fs::exists(log)) {
    s.state = fs::exists(folder.resolved_toml()) ? RunState::running : RunState::not_started;
    return s;
  }
  // RunRecorder::progress: "[lowering  ]  42.0%  t = ..."
  static const std::regex progress(R"(^\[(\S+)\s*\]\s+([0-9.]+)%)");
  std::istringstream lines(read_text_file(log));
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    s.last_line = line;
    std::smatch m;
    if (std::regex_search(line, m, progress)) {
      s.stage = m[1];
      s.percent = std::stod(m[2]);
    }
  }
  std::error_code ec;
  const auto written = fs::last_write_time(log, ec);
  if (!ec) s.seconds_since_log = std::chrono::duration<double>(fs::file_time_type::clock::now() - written).count();
  if (s.last_line.empty())
    s.state = RunState::running;  // opened, nothing said yet
  else if (starts_with(s.last_line, kErrorLine))
    s.state = RunState::failed;
  else if (starts_with(s.last_line, kStopLine))
    s.state = RunState::stopped;
  else
    s.state = RunState::running;
  return s;
}

std::vector<RunStatus> study_status(const StudyDefinition& study, const StudyScale& scale, const fs::path& out,
                                    const fs::path& presets) {
  std::vector<RunStatus> all;
  for (const StudyCase& c : study.cases)
    for (const CaseRun& run : case_runs(study, c, scale, out, presets)) {
      RunStatus s = run_status(run.dir);
      s.title = run.replicate ? fmt::format("{} seed {}", c.name, run.seed) : c.name;
      all.push_back(std::move(s));
    }
  return all;
}

std::string status_text(const std::vector<RunStatus>& runs) {
  std::size_t width = 4;
  for (const RunStatus& r : runs) width = std::max(width, r.title.size());
  std::string text;
  std::size_t count[5] = {};
  for (const RunStatus& r : runs) {
    ++count[int(r.state)];
    std::string detail;
    const std::string where =
        r.percent >= 0.0 ? fmt::format("{} {:.1f} %", r.stage, r.percent) : std::string("starting, no progress line yet");
    const std::string age = r.seconds_since_log >= 0.0 ? fmt::format("; run.log written {} ago", format_age(r.seconds_since_log)) : "";
    switch (r.state) {
      case RunState::not_started: detail = "not started"; break;
      case RunState::finished: detail = "finished"; break;
      case RunState::running: detail = fmt::format("running: {}{}", where, age); break;
      case RunState::stopped:
        detail = fmt::format("stopped with a checkpoint at {}{} (submit or run the study again to resume it)", where, age);
        break;
      case RunState::failed: detail = fmt::format("failed: {}", r.last_line); break;
    }
    text += fmt::format("  {:<{}}  {}\n", r.title, width, detail);
  }
  std::string summary;
  for (RunState s : {RunState::finished, RunState::running, RunState::stopped, RunState::failed, RunState::not_started})
    if (count[int(s)]) summary += fmt::format("{}{} {}", summary.empty() ? "" : ", ", count[int(s)], to_string(s));
  return text + fmt::format("{} runs: {}\n", runs.size(), summary.empty() ? "none" : summary);
}

}  // namespace trapdem
