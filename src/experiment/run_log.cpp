#include "experiment/run_log.hpp"

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

RunLog::RunLog(std::filesystem::path path, bool quiet, LineSink terminal)
    : path_(std::move(path)), quiet_(quiet), terminal_(std::move(terminal)) {
  file_ = std::fopen(path_.c_str(), "a");
  if (!file_) throw FileError(fmt::format("cannot open {} for writing: {}", path_.string(), std::strerror(errno)));
}

RunLog::~RunLog() {
  if (file_) std::fclose(file_);
}

void RunLog::say(const std::string& line) {
  if (!quiet_) terminal_.say(line);
  note(line);
}

void RunLog::warn(const std::string& line) {
  terminal_.warn(line);
  note(line);
}

void RunLog::note(const std::string& line) {
  errno = 0;
  // fflush after every line: a killed run keeps its log up to its last line.
  if (std::fputs(line.c_str(), file_) < 0 || std::fputc('\n', file_) == EOF || std::fflush(file_) != 0) {
    const int error = errno;
    std::clearerr(file_);
    throw FileError(fmt::format("cannot write {}: {} (is the disk full?); the run stops here, resume it with --resume "
                                "once there is room", path_.string(), error ? std::strerror(error) : "write failed"));
  }
}

}  // namespace trapdem
