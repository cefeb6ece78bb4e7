#pragma once
// Where a workflow's lines for its user go. By default the process's own streams (the program's
// terminal: progress on stdout, warnings on stderr); a front end may give its own, as the Python
// module gives sys.stdout and sys.stderr, so that a notebook shows a run's progress in the cell
// that started it (a kernel's file descriptors are not the notebook's).
#include <functional>
#include <string>

namespace trapdem {

struct LineSink {
  std::function<void(const std::string& line)> out;  // progress and results; empty: stdout
  std::function<void(const std::string& line)> err;  // warnings; empty: stderr

  // The line to `out`, else to stdout, flushed (a line at a time, so a killed run's last line shows).
  void say(const std::string& line) const;
  // The line to `err`, else to stderr.
  void warn(const std::string& line) const;
};

}  // namespace trapdem
