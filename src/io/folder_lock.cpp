#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

std::string holder_text(int fd) {
  char buffer[256] = {};
  const ssize_t n = pread(fd, buffer, sizeof(buffer) - 1, 0);
  std::string text = n > 0 ? std::string(buffer, std::size_t(n)) : std::string();
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text.empty() ? "it has not written its pid yet" : text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown host";
  return name;
}

}  // namespace

FolderLock::FolderLock(std::filesystem::path lock_file, const std::string& what_to_do)
    : path_(std::move(lock_file)) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw FileError(fmt::format("cannot open the lock file {}: {}", path_.string(), std::strerror(errno)));
  int rc;
  do rc = ::flock(fd_, LOCK_EX | LOCK_NB);
  while (rc != 0 && errno == EINTR);
  if (rc != 0) {
    const int error = errno;
    const std::string holder = error == EWOULDBLOCK ? holder_text(fd_) : std::string();
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw InputError(fmt::format("{} is in use by another trapdem process ({}; lock {}): {}", path_.parent_path().string(),
                                   holder, path_.string(), what_to_do));
    throw FileError(fmt::format("cannot lock {}: {}", path_.string(), std::strerror(error)));
  }
  // Who holds it, for the message another process gets. Best effort: the lock is the flock itself.
  const std::string holder = fmt::format("pid {} on {}\n", static_cast<long>(getpid()), host_name());
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, holder.data(), holder.size(), 0);
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the only descriptor releases the flock
}

}  // namespace trapdem
