#pragma once
// A run folder's run.log: every line the run says, also on the terminal unless quiet (the terminal
// being a LineSink: a notebook's cell from Python). Opened
// before anything else of the run is written, so the log holds the run from its first line (and
// the error that stops it); a line that cannot be written (a full disk) is a FileError at once,
// not a run that goes on for hours with an empty log (issue 14).
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/line_sink.hpp"

namespace trapdem {

class RunLog {
 public:
  // Opens `path` for appending; FileError naming it if it cannot. The terminal's lines go to
  // `terminal` (default: this process's stdout and stderr).
  RunLog(std::filesystem::path path, bool quiet, LineSink terminal = {});
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  // A line for the log and (unless quiet) the terminal; FileError naming the file if the write or
  // its flush fails.
  void say(const std::string& line);
  // A line for the log and the terminal's stderr even when quiet: what the user must know (a
  // resume that cannot carry on and starts again); FileError as say().
  void warn(const std::string& line);
  // A line for the log only (checkpoint notes); FileError as say().
  void note(const std::string& line);

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  bool quiet_;
  LineSink terminal_;
};

}  // namespace trapdem
