#pragma once
// Helpers shared by the tests: a scratch folder that cleans up after itself (every test's scratch
// under /tmp is one, so a failed test leaves nothing: tests/scratch_check.sh), whole-file reads,
// and a scoped file-size limit that makes writes fail as on a full disk.
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

namespace trapdem::io_testing {

class ScratchDir {
 public:
  // A new folder PREFIX-XXXXXX under the temporary directory (mkdtemp: unique, also between the
  // parallel processes of ctest -j), removed with everything in it when this goes (a test that
  // fails included; a helper's function-local static one at the process's exit).
  explicit ScratchDir(const std::string& prefix = "trapdem-io") {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names in the folder (to check that no temporary is left behind).
  std::size_t entry_count() const {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(path_)) ++n;
    return n;
  }

 private:
  std::filesystem::path path_;
};

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
