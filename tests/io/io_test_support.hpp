#pragma once
// Helpers shared by the file tests: the scratch folder (tests/scratch_dir.hpp, here as
// io_testing::ScratchDir too), whole-file reads, and a scoped file-size limit that makes writes fail
// as on a full disk.
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "../scratch_dir.hpp"

namespace trapdem::io_testing {

using test::ScratchDir;  // tests/scratch_dir.hpp

inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// While alive, no file of this process may grow beyond `bytes`: a write past it fails with EFBIG,
// which is what a full disk looks like to the writer (ENOSPC), without needing a small file system.
// SIGXFSZ, which would kill the process, is ignored meanwhile. Works for root too.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

// The message of the FileError `action` throws ("" if it throws none).
inline std::string file_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace trapdem::io_testing
