// The tests' scratch folder (tests/scratch_dir.hpp): unique, removed when it goes (moved-from ones
// remove nothing), kept and named on stderr under TRAPDEM_KEEP_SCRATCH=1.
#include "../scratch_dir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace fs = std::filesystem;
using trapdem::test::ScratchDir;

namespace {

// Sets TRAPDEM_KEEP_SCRATCH (or unsets it for nullptr) while alive and restores what the suite was
// started with afterwards.
class KeepScratchVariable {
 public:
  explicit KeepScratchVariable(const char* value) {
    if (const char* before = std::getenv(kName)) before_ = before;
    if (value) ::setenv(kName, value, 1);
    else ::unsetenv(kName);
  }
  ~KeepScratchVariable() {
    if (before_) ::setenv(kName, before_->c_str(), 1);
    else ::unsetenv(kName);
  }

 private:
  static constexpr const char* kName = "TRAPDEM_KEEP_SCRATCH";
  std::optional<std::string> before_;
};

TEST(ScratchDir, MakesAUniqueFolderAndRemovesItWithItsContents) {
  const KeepScratchVariable unset(nullptr);
  fs::path first, second;
  {
    const ScratchDir a("trapdem-scratch-test");
    const ScratchDir b("trapdem-scratch-test");
    first = a.path();
    second = b.path();
    EXPECT_NE(first, second);
    EXPECT_EQ(first.parent_path(), fs::temp_directory_path());
    EXPECT_EQ(first.filename().string().rfind("trapdem-scratch-test-", 0), 0u) << first;
    ASSERT_TRUE(fs::is_directory(first));
    fs::create_directories(a / "sub" / "deeper");
    std::ofstream(a / "sub" / "file.txt") << "x";
    EXPECT_EQ(a.entry_count(), 1u);
  }
  EXPECT_FALSE(fs::exists(first));
  EXPECT_FALSE(fs::exists(second));
}

TEST(ScratchDir, AMovedFolderIsRemovedOnceByItsLastOwner) {
  const KeepScratchVariable unset(nullptr);
  fs::path path;
  {
    ScratchDir outer("trapdem-scratch-test");
    path = outer.path();
    {
      ScratchDir moved(std::move(outer));
      EXPECT_EQ(moved.path(), path);
    }
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(ScratchDir, KeptAndNamedOnStderrWhenAskedTo) {
  const KeepScratchVariable keep("1");
  fs::path path;
  ::testing::internal::CaptureStderr();
  {
    const ScratchDir dir("trapdem-scratch-test");
    path = dir.path();
    std::ofstream(dir / "what-the-test-wrote.txt") << "x";
  }
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(fs::exists(path / "what-the-test-wrote.txt"));
  EXPECT_EQ(printed, "kept scratch folder " + path.string() + " (TRAPDEM_KEEP_SCRATCH=1)\n");
  fs::remove_all(path);
}

TEST(ScratchDir, OnlyOneMeansKeep) {
  const KeepScratchVariable zero("0");
  fs::path path;
  { path = ScratchDir("trapdem-scratch-test").path(); }
  EXPECT_FALSE(fs::exists(path));
}

TEST(ScratchDir, APrefixTheScratchCheckWouldNotSeeIsRefused) {
  EXPECT_THROW(ScratchDir("scratch"), std::invalid_argument);
}

}  // namespace
