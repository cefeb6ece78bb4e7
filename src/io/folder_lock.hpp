#pragma once
// An exclusive lock on a folder that one process writes: `trapdem run` holds its run folder's lock
// from the first line of run.log to its last, so that a second process (a study submitted twice, a
// run resumed by hand while its Slurm task still runs) is refused with a clear error instead of
// both writing the same checkpoint.h5 and snapshots. The lock is flock(2) on a file in the folder
// (run.lock for a run folder): the kernel releases it when the process ends, however it ends (a
// crash or SIGKILL leaves no stale lock to clear by hand); Linux NFS clients map it to a POSIX
// lock, which the server keeps, so it also holds between the nodes of a cluster that share the folder.
#include <filesystem>
#include <string>

namespace trapdem {

class FolderLock {
 public:
  // Takes the lock on `lock_file` (created if missing; its folder must exist), writing this
  // process's pid and host into it. Throws InputError if another process holds it ("<folder> is in
  // use by another trapdem process (<what it wrote>; lock <file>): " + what_to_do), FileError if
  // the file cannot be opened or locked.
  FolderLock(std::filesystem::path lock_file, const std::string& what_to_do);
  ~FolderLock();  // releases the lock (the file stays: removing it would race a process taking it)
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace trapdem
