#include "io/hdf5_probe.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/hdf5_walk.hpp"

// AddressSanitizer (and ThreadSanitizer, MemorySanitizer) reserve terabytes of address space for
// their shadow memory: an address-space limit in the child would fail its first allocation.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TRAPDEM_SHADOW_MEMORY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define TRAPDEM_SHADOW_MEMORY 1
#endif
#endif

// Present in programs built with a sanitizer: a report calls the callback before the process
// dies (libFuzzer sets its own there, which would save the input as a finding of the parent).
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace trapdem {

namespace fs = std::filesystem;

namespace {

// The child's exit statuses besides 0.
constexpr int kWalkFailed = 3;        // an exception other than the ones below
constexpr int kOutOfMemory = 4;       // std::bad_alloc: the memory limit
constexpr int kSanitizerReport = 86;  // a sanitizer's report (printed on stderr)

struct ProbedFile {
  std::string name;
  FileIdentity identity;
};

std::mutex g_mutex;
Hdf5ProbeLimits g_limits;
// The probes that passed, by the path probed: every file they reached, as it was then.
std::map<std::string, std::vector<ProbedFile>> g_passed;
// Files that passed and hold no external link: unchanged, they need no walk again.
std::set<FileIdentity> g_self_contained;

// Files this process wrote: device, inode, size, modification time (a rename changes the change
// time, not these).
using Written = std::tuple<std::uint64_t, std::uint64_t, std::int64_t, std::int64_t>;
std::set<Written> g_written;

Written written_key(const FileIdentity& id) { return {id.device, id.inode, id.size, id.modified_ns}; }

bool unchanged(const std::vector<ProbedFile>& files) {
  for (const ProbedFile& f : files) {
    if (identity_of(f.name) != f.identity) return false;
  }
  return true;
}

std::string identity_text(const FileIdentity& id) {
  return fmt::format("{} {} {} {} {}", id.device, id.inode, id.size, id.modified_ns, id.changed_ns);
}

std::int64_t now_ns() {
  timespec t{};
  ::clock_gettime(CLOCK_REALTIME, &t);
  return std::int64_t(t.tv_sec) * 1000000000 + t.tv_nsec;
}

void send(int fd, const std::string& line) {
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(kWalkFailed);  // the parent is gone
    done += std::size_t(n);
  }
}

void died_of_a_sanitizer_report() { ::_exit(kSanitizerReport); }

// The address space the process maps now (the first field of /proc/self/statm, in pages). Not
// under a sanitizer (TRAPDEM_SHADOW_MEMORY), whose shadow memory no address-space limit allows.
[[maybe_unused]] std::size_t mapped_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return std::size_t(pages) * std::size_t(::sysconf(_SC_PAGESIZE));
}

// The child: reports on `fd` one line per event ("F <identity> <name>": a file reached, "E
// <identity>": it links out, "@ <where>": the walk goes on there, "OK": done) and leaves with
// _exit, never returning into the program.
[[noreturn]] void child(int fd, const fs::path& path, const Hdf5ProbeLimits& limits) {
  struct sigaction plain {};
  plain.sa_handler = SIG_DFL;
  sigemptyset(&plain.sa_mask);
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS, SIGXCPU, SIGINT, SIGTERM, SIGPIPE})
    ::sigaction(s, &plain, nullptr);
  sigset_t all;
  sigemptyset(&all);
  ::sigprocmask(SIG_SETMASK, &all, nullptr);
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(died_of_a_sanitizer_report);

  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  const rlimit cpu{rlim_t(limits.cpu.count()), rlim_t(limits.cpu.count() + 1)};
  ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef TRAPDEM_SHADOW_MEMORY
  const rlim_t space = rlim_t(mapped_bytes() + limits.memory_bytes);
  const rlimit memory{space, space};
  ::setrlimit(RLIMIT_AS, &memory);
#endif

  int status = 0;
  try {
    Hdf5WalkSink sink;
    sink.enter_file = [fd](const std::string& name, const FileIdentity& id) {
      send(fd, fmt::format("F {} {}\n", identity_text(id), name));
      return g_self_contained.count(id) == 0 && g_written.count(written_key(id)) == 0;
    };
    sink.links_out = [fd](const FileIdentity& id) { send(fd, fmt::format("E {}\n", identity_text(id))); };
    sink.at = [fd](const std::string& where) { send(fd, "@ " + where + "\n"); };
    walk_hdf5_file(path, sink);
    send(fd, "OK\n");
  } catch (const std::bad_alloc&) {
    status = kOutOfMemory;
  } catch (...) {
    status = kWalkFailed;
  }
  ::_exit(status);
}

// What the parent heard from the child.
struct Answer {
  std::vector<ProbedFile> files;
  std::set<FileIdentity> linking_out;
  std::string where;  // the last place announced
  bool finished = false;
};

FileIdentity parse_identity(std::istringstream& in) {
  FileIdentity id;
  in >> id.device >> id.inode >> id.size >> id.modified_ns >> id.changed_ns;
  return id;
}

void take_line(const std::string& line, Answer& a) {
  if (line.rfind("@ ", 0) == 0) {
    a.where = line.substr(2);
  } else if (line == "OK") {
    a.finished = true;
  } else if (line.rfind("F ", 0) == 0 || line.rfind("E ", 0) == 0) {
    std::istringstream in(line.substr(2));
    const FileIdentity id = parse_identity(in);
    if (line[0] == 'E') {
      a.linking_out.insert(id);
    } else {
      std::string name;
      in.get();
      std::getline(in, name);
      a.files.push_back({name, id});
    }
  }
}

std::string signal_name(int s) {
  const char* name = ::strsignal(s);
  return name ? fmt::format("signal {}: {}", s, name) : fmt::format("signal {}", s);
}

void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

void set_hdf5_probe_limits(const Hdf5ProbeLimits& limits) {
  std::lock_guard lock(g_mutex);
  g_limits = limits;
}

void forget_probed_hdf5_files() {
  std::lock_guard lock(g_mutex);
  g_passed.clear();
  g_self_contained.clear();
  g_written.clear();
}

void note_hdf5_file_written(const fs::path& path) {
  std::lock_guard lock(g_mutex);
  if (const std::optional<FileIdentity> identity = identity_of(path)) g_written.insert(written_key(*identity));
}

void probe_hdf5_file(const fs::path& path) {
  std::lock_guard lock(g_mutex);
  const std::optional<FileIdentity> identity = identity_of(path);
  if (!identity) return;  // the reader says that the file is missing
  if (g_self_contained.count(*identity) || g_written.count(written_key(*identity))) return;
  if (const auto it = g_passed.find(path.string()); it != g_passed.end() && unchanged(it->second)) return;

  const Hdf5ProbeLimits limits = g_limits;
  const std::int64_t settled_before =
      now_ns() - std::chrono::duration_cast<std::chrono::nanoseconds>(limits.settled).count();
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
    throw FileError(fmt::format("{}: cannot check the file before reading it (pipe: {})", path.string(),
                                std::strerror(errno)));
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    throw FileError(fmt::format("{}: cannot check the file before reading it (fork: {})", path.string(),
                                std::strerror(err)));
  }
  if (pid == 0) {
    ::close(pipe_fds[0]);
    child(pipe_fds[1], path, limits);
  }
  ::close(pipe_fds[1]);

  // Listen until the child closes its end (it exits) or the wall-clock limit passes.
  Answer answer;
  answer.where = path.string();
  std::string pending;
  const auto deadline = std::chrono::steady_clock::now() + limits.wall;
  bool timed_out = false;
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{pipe_fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, std::size_t(n));
    for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1))
      take_line(pending.substr(0, end), answer);
  }
  ::close(pipe_fds[0]);
  if (timed_out) {
    kill_and_reap(pid);
    throw FileError(fmt::format("libhdf5 did not finish reading {} within {} s (the limit): the file is damaged, or "
                                "its storage does not answer",
                                answer.where, limits.wall.count() / 1000.0));
  }
  int status = 0;
  pid_t reaped;
  while ((reaped = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  const bool exited_ok = reaped == pid ? WIFEXITED(status) && WEXITSTATUS(status) == 0 : answer.finished;
  if (answer.finished && exited_ok) {
    bool all_settled = true;
    for (const ProbedFile& f : answer.files) {
      const bool settled = std::max(f.identity.modified_ns, f.identity.changed_ns) < settled_before;
      if (settled && !answer.linking_out.count(f.identity)) g_self_contained.insert(f.identity);
      all_settled = all_settled && settled;
    }
    if (all_settled) g_passed[path.string()] = std::move(answer.files);
    return;
  }
  const std::string where = answer.where;
  if (reaped == pid && WIFSIGNALED(status)) {
    const int s = WTERMSIG(status);
    if (s == SIGXCPU)
      throw FileError(fmt::format("libhdf5 used more than {} s of CPU time reading {} (the limit; {}): the file is "
                                  "damaged",
                                  limits.cpu.count(), where, signal_name(s)));
    throw FileError(fmt::format("libhdf5 crashed ({}) reading {}: the file is damaged", signal_name(s), where));
  }
  const int code = reaped == pid && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == kOutOfMemory)
    throw FileError(fmt::format("libhdf5 needed more than {} MiB reading {} (the limit): the file is damaged",
                                limits.memory_bytes >> 20, where));
  if (code == kSanitizerReport)
    throw FileError(fmt::format("the check of {} before reading it ended with a sanitizer report (above) at {}: the "
                                "file is damaged",
                                path.string(), where));
  throw FileError(fmt::format("the check of {} before reading it failed at {} (the checking process ended with "
                              "status {}{})",
                              path.string(), where, code, answer.finished ? "" : ", without finishing"));
}

}  // namespace trapdem
