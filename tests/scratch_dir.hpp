#pragma once
// A test's scratch folder: every test that writes files writes them into one of these, so that two
// suites running at once (two checkouts, ctest -j) never share a folder and a test that fails leaves
// nothing behind in /tmp (tests/scratch_check.sh checks that after the suite).
//
// TRAPDEM_KEEP_SCRATCH=1 in the environment keeps the folders, each one's path printed to stderr
// when it would have been removed ("kept scratch folder ..."), to look at what a failing test wrote.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

#include <unistd.h>

namespace trapdem::test {

class ScratchDir {
 public:
  // A new folder PREFIX-XXXXXX under the temporary directory (mkdtemp: unique, also between the
  // parallel processes of ctest -j and between suites of different checkouts), removed with
  // everything in it when this goes (a test that fails included; a function-local static one at the
  // process's exit). PREFIX starts with "trapdem", the name tests/scratch_check.sh looks for.
  explicit ScratchDir(const std::string& prefix = "trapdem-test") {
    if (prefix.rfind("trapdem", 0) != 0)
      throw std::invalid_argument("scratch folder prefix '" + prefix + "' does not start with 'trapdem'");
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ScratchDir(ScratchDir&& other) noexcept : path_(std::exchange(other.path_, {})) {}
  ScratchDir& operator=(ScratchDir&& other) noexcept {
    if (this != &other) {
      release();
      path_ = std::exchange(other.path_, {});
    }
    return *this;
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() { release(); }

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }
  // Names in the folder (to check that no temporary is left behind).
  std::size_t entry_count() const {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(path_)) ++n;
    return n;
  }

  // Whether TRAPDEM_KEEP_SCRATCH=1 asks to keep scratch folders.
  static bool keep_requested() {
    const char* keep = std::getenv("TRAPDEM_KEEP_SCRATCH");
    return keep && std::string(keep) == "1";
  }

 private:
  void release() {
    if (path_.empty()) return;  // moved from
    if (keep_requested()) {
      std::cerr << "kept scratch folder " << path_.string() << " (TRAPDEM_KEEP_SCRATCH=1)\n";
    } else {
      std::error_code ec;  // a test that made a file read-only must not keep its folder
      std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ec);
      std::filesystem::remove_all(path_, ec);
    }
    path_.clear();
  }

  std::filesystem::path path_;
};

}  // namespace trapdem::test
