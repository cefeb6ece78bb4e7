// Atomic replacement: the target is either the old complete file or the new complete file, never
// a partial one, and failures name the path.
#include "io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "core/errors.hpp"
#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

TEST(AtomicFile, CreatesAndReplacesWithoutLeavingTemporaries) {
  ScratchDir dir;
  const auto path = dir / "resolved.toml";
  write_text_atomically(path, "first\n");
  EXPECT_EQ(read_all(path), "first\n");
  write_text_atomically(path, "second, longer\n");
  EXPECT_EQ(read_all(path), "second, longer\n");
  EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(AtomicFile, FailingWriterKeepsThePreviousFile) {
  ScratchDir dir;
  const auto path = dir / "state.txt";
  write_text_atomically(path, "good\n");
  try {
    write_atomically(path, [](const std::filesystem::path& temporary) {
      std::ofstream(temporary) << "half of it";
      throw std::runtime_error("simulated crash while writing");
    });
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_NE(what.find("simulated crash"), std::string::npos) << what;
  }
  EXPECT_EQ(read_all(path), "good\n");
  EXPECT_EQ(dir.entry_count(), 1u);  // the temporary is gone
}

TEST(AtomicFile, InputErrorsFromTheWriterPassThrough) {
  ScratchDir dir;
  EXPECT_THROW(write_atomically(dir / "x", [](const std::filesystem::path&) { throw InputError("bad key"); }),
               InputError);
  EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(AtomicFile, MissingFolderIsAClearError) {
  ScratchDir dir;
  const auto path = dir / "no-such-folder" / "out.txt";
  try {
    write_text_atomically(path, "x");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, FullDiskKeepsThePreviousFile) {
  ScratchDir dir;
  const auto path = dir / "big.txt";
  write_text_atomically(path, "small and good\n");
  const std::string big(1 << 20, 'x');
  {
    FileSizeLimit limit(64 * 1024);  // writes past 64 KiB fail as on a full disk
    EXPECT_THROW(write_text_atomically(path, big), FileError);
  }
  EXPECT_EQ(read_all(path), "small and good\n");
  EXPECT_EQ(dir.entry_count(), 1u);
}

// Root writes into read-only folders (CAP_DAC_OVERRIDE), so the write is tried in a forked child
// that first gives up root for the unprivileged "nobody" (65534) where the test runs as root. The
// child's verdict comes back as its exit status; the parent checks the old file.
TEST(AtomicFile, UnwritableFolderIsAClearError) {
  ScratchDir dir;
  const auto path = dir / "out.txt";
  write_text_atomically(path, "old\n");
  namespace fs = std::filesystem;
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                  fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  enum Verdict { kClearError = 0, kNoError = 10, kPathNotNamed = 11, kOtherException = 12, kCannotDropRoot = 13 };
  const pid_t child = ::fork();
  ASSERT_GE(child, 0) << "fork failed";
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0 || ::geteuid() == 0)) ::_exit(kCannotDropRoot);
    int verdict = kNoError;
    try {
      write_text_atomically(path, "new\n");
    } catch (const FileError& e) {
      verdict = std::string(e.what()).find(path.string()) != std::string::npos ? kClearError : kPathNotNamed;
    } catch (...) {
      verdict = kOtherException;
    }
    ::_exit(verdict);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), kClearError)
      << "10: the write into a read-only folder succeeded; 11: the FileError does not name the file; "
         "12: another exception; 13: could not give up root";
  EXPECT_EQ(read_all(path), "old\n");
}

TEST(AtomicFile, ModifyStartsFromACopyOfTheOldFile) {
  ScratchDir dir;
  const auto path = dir / "log.txt";
  write_text_atomically(path, "one\n");
  modify_atomically(path, [](const std::filesystem::path& temporary) {
    std::ofstream(temporary, std::ios::app) << "two\n";
  });
  EXPECT_EQ(read_all(path), "one\ntwo\n");
  EXPECT_THROW(modify_atomically(path,
                                 [](const std::filesystem::path& temporary) {
                                   std::ofstream(temporary, std::ios::app) << "three";
                                   throw std::runtime_error("crash");
                                 }),
               FileError);
  EXPECT_EQ(read_all(path), "one\ntwo\n");
  EXPECT_EQ(dir.entry_count(), 1u);
}
