// FolderLock (io/folder_lock.hpp): one holder at a time, a clear refusal naming the holder, and no
// stale lock after its holder dies, however it dies.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <optional>
#include <string>

#include "core/errors.hpp"
#include "io/folder_lock.hpp"
#include "io_test_support.hpp"

namespace trapdem {
namespace {

using io_testing::read_all;
using io_testing::ScratchDir;

std::string refusal(const std::filesystem::path& file) {
  try {
    FolderLock second(file, "do something else");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FolderLock, ASecondHolderIsRefusedNamingTheFirst) {
  ScratchDir dir;
  const auto file = dir / "run.lock";
  {
    FolderLock first(file, "unused");
    EXPECT_EQ(read_all(file), "pid " + std::to_string(getpid()) + " on " + [] {
      char name[256] = {};
      gethostname(name, sizeof(name) - 1);
      return std::string(name);
    }() + "\n");
    // flock locks belong to open file descriptions: a second open in this very process conflicts,
    // as another process's would.
    const std::string message = refusal(file);
    EXPECT_NE(message.find(dir.path().string() + " is in use by another trapdem process (pid " +
                           std::to_string(getpid())),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("lock " + file.string() + "): do something else"), std::string::npos) << message;
  }
  EXPECT_EQ(refusal(file), "") << "released when its holder is destroyed";
}

TEST(FolderLock, AKilledHolderLeavesNoStaleLock) {
  ScratchDir dir;
  const auto file = dir / "run.lock";
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ready[0]);
    try {
      FolderLock held(file, "unused");
      const char c = 1;
      if (write(ready[1], &c, 1) != 1) _exit(3);
      pause();  // until SIGKILL: the destructor never runs
    } catch (...) {
      _exit(2);
    }
    _exit(0);
  }
  close(ready[1]);
  char c = 0;
  ASSERT_EQ(read(ready[0], &c, 1), 1) << "the child could not take the lock";
  close(ready[0]);
  const std::string message = refusal(file);
  EXPECT_NE(message.find("(pid " + std::to_string(child) + " on "), std::string::npos) << message;
  kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(refusal(file), "") << "the kernel releases the lock of a killed process";
}

TEST(FolderLock, AFolderThatDoesNotExistIsAFileError) {
  ScratchDir dir;
  EXPECT_THROW(FolderLock(dir / "missing" / "run.lock", "unused"), FileError);
}

}  // namespace
}  // namespace trapdem
