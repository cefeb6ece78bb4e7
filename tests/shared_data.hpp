#pragma once
// The shared data (../shared beside the checkout: photographs, reference results) are part of the
// test suite. A test that needs them fails when they are missing, naming the file and where it was
// looked for: a skipped test would pass a suite that checked nothing.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace trapdem::test {

inline std::filesystem::path shared_dir() { return std::filesystem::path(TRAPDEM_SHARED_DIR).lexically_normal(); }

// Success when every file exists; otherwise a failure listing the missing ones.
inline ::testing::AssertionResult shared_files_present(const std::vector<std::filesystem::path>& files) {
  std::string missing;
  for (const auto& f : files)
    if (!std::filesystem::is_regular_file(f)) missing += "\n  " + f.string();
  if (missing.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "shared data missing (the tests read " << shared_dir().string()
         << ", the shared/ folder beside the checkout):" << missing;
}

}  // namespace trapdem::test
