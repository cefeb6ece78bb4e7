#include "core/host_load.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

namespace trapdem {

namespace fs = std::filesystem;

namespace {

// The cgroup (v2) this process is in: "0::/path" in /proc/self/cgroup.
fs::path own_cgroup() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) return fs::path("/sys/fs/cgroup") / fs::path(line.substr(3)).relative_path();
  return {};
}

// The tightest quota on the way from this process's cgroup up to the root (a parent's cpu.max
// limits its children too).
int cgroup_quota_of_this_process() {
  fs::path group = own_cgroup();
  if (group.empty()) return 0;
  int tightest = 0;
  for (;;) {
    std::ifstream in(group / "cpu.max");
    std::string text;
    if (in && std::getline(in, text)) {
      const int quota = cgroup_quota_cores(text);
      if (quota > 0 && (tightest == 0 || quota < tightest)) tightest = quota;
    }
    if (group == "/sys/fs/cgroup" || !group.has_parent_path() || group.parent_path() == group) break;
    group = group.parent_path();
    if (group.string().size() < std::string("/sys/fs/cgroup").size()) break;
  }
  return tightest;
}

std::string read_small_file(int fd) {
  char buffer[1024] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof(buffer) - 1, 0);
  return n > 0 ? std::string(buffer, std::size_t(n)) : std::string();
}

bool flock_nonblocking(int fd, int operation) {
  int rc;
  do rc = ::flock(fd, operation | LOCK_NB);
  while (rc != 0 && errno == EINTR);
  return rc == 0;
}

}  // namespace

std::string UsableCores::describe() const {
  return fmt::format("{} core{} (affinity mask {}, {})", count, count == 1 ? "" : "s", affinity,
                     cgroup_quota > 0 ? fmt::format("cgroup quota {}", cgroup_quota) : std::string("no cgroup quota"));
}

int cgroup_quota_cores(const std::string& cpu_max) {
  std::istringstream in(cpu_max);
  std::string quota_text;
  long long period = 0;
  if (!(in >> quota_text >> period) || period <= 0 || quota_text == "max") return 0;
  char* end = nullptr;
  const long long quota = std::strtoll(quota_text.c_str(), &end, 10);
  if (end == quota_text.c_str() || *end != '\0' || quota <= 0) return 0;
  return int((quota + period - 1) / period);
}

UsableCores usable_cores() {
  UsableCores cores;
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0)
    cores.affinity = std::max(1, CPU_COUNT(&set));
  else
    cores.affinity = int(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  cores.cgroup_quota = cgroup_quota_of_this_process();
  cores.count = cores.cgroup_quota > 0 ? std::min(cores.affinity, cores.cgroup_quota) : cores.affinity;
  return cores;
}

fs::path run_registry_dir() {
  if (const char* dir = std::getenv("TRAPDEM_RUN_REGISTRY"); dir && *dir)
    return std::string_view(dir) == "none" ? fs::path() : fs::path(dir);
  const std::string name = fmt::format("trapdem-runs-{}", static_cast<long>(::getuid()));
  std::error_code ec;
  if (fs::is_directory("/dev/shm", ec)) return fs::path("/dev/shm") / name;
  return fs::temp_directory_path(ec) / ("." + name);
}

RunRegistration::RunRegistration(int threads, const std::string& what) {
  const fs::path dir = run_registry_dir();
  if (dir.empty()) return;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return;
  ::chmod(dir.c_str(), 0700);  // only this user's runs: the folder is this user's alone
  // Written under a temporary name, locked, then renamed: a reader never finds it unlocked.
  const fs::path temporary = dir / fmt::format(".run-{}.tmp", static_cast<long>(::getpid()));
  const int fd = ::open(temporary.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return;
  if (!flock_nonblocking(fd, LOCK_EX)) {
    ::close(fd);
    return;
  }
  const std::string text = fmt::format("{}\n{}\n", threads, what);
  const fs::path path = dir / fmt::format("run-{}", static_cast<long>(::getpid()));
  if (::pwrite(fd, text.data(), text.size(), 0) != ssize_t(text.size()) ||
      ::rename(temporary.c_str(), path.c_str()) != 0) {
    ::unlink(temporary.c_str());
    ::close(fd);
    return;
  }
  fd_ = fd;
  path_ = path;
}

RunRegistration::~RunRegistration() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // before the lock goes: nobody finds it unlocked
  ::close(fd_);
}

std::vector<RegisteredRun> other_registered_runs() {
  std::vector<RegisteredRun> runs;
  const fs::path dir = run_registry_dir();
  if (dir.empty()) return runs;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) return runs;
  const long own = static_cast<long>(::getpid());
  for (const fs::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("run-", 0) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + 4, &end, 10);
    if (end == name.c_str() + 4 || *end != '\0' || pid == own) continue;
    const int fd = ::open(entry.path().c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) continue;
    if (flock_nonblocking(fd, LOCK_SH)) {
      // Nobody holds it: its process ended without removing it (killed). Stale: removed.
      ::unlink(entry.path().c_str());
      ::close(fd);
      continue;
    }
    std::istringstream text(read_small_file(fd));
    ::close(fd);
    RegisteredRun run;
    run.pid = int(pid);
    if (!(text >> run.threads) || run.threads < 1) run.threads = 1;
    text.ignore(1);
    std::getline(text, run.what);
    runs.push_back(run);
  }
  return runs;
}

int HostLoad::total_threads() const {
  return std::accumulate(others.begin(), others.end(), threads * local_ranks,
                         [](int sum, const RegisteredRun& r) { return sum + r.threads; });
}

std::string HostLoad::warning(const std::string& wait_policy, bool restart_failed) const {
  if (!oversubscribed()) return {};
  std::string text = "this host oversubscribed: ";
  if (process_oversubscribed())
    text += fmt::format("this process runs {} threads on its {}", threads, cores.describe());
  if (process_oversubscribed() && host_oversubscribed()) text += "; ";
  if (host_oversubscribed()) {
    text += fmt::format("{} threads of trapdem runs on the host's {} core{}: this run {} thread{}", total_threads(),
                        host_cores, host_cores == 1 ? "" : "s", threads, threads == 1 ? "" : "s");
    if (local_ranks > 1) text += fmt::format(" x {} ranks here", local_ranks);
    for (const RegisteredRun& r : others)
      text += fmt::format(", trapdem pid {} {} thread{}{}", r.pid, r.threads, r.threads == 1 ? "" : "s",
                          r.what.empty() ? std::string() : fmt::format(" ({})", r.what));
  }
  text += ". Every run slows more than in proportion; ";
  std::string policy = wait_policy;
  for (char& c : policy) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (policy == "passive")
    text += "this run's threads wait passively (they sleep instead of spinning)";
  else if (policy.empty() && restart_failed)
    text += "this run's threads spin while they wait (the program could not restart itself with "
            "OMP_WAIT_POLICY=passive): set that variable, or use fewer threads (--threads)";
  else if (policy.empty())
    // libgomp reads the policy once, when it is loaded: a run that found the host free at its
    // start and was joined later cannot change how its threads wait (wait_policy.hpp).
    text += "this run's threads spin while they wait (the host was not crowded when it started, and how "
            "threads wait is fixed at the start): set OMP_WAIT_POLICY=passive, or use fewer threads (--threads)";
  else
    text += fmt::format("this run's threads spin while they wait (OMP_WAIT_POLICY={} was set by hand): set it to "
                        "passive, or use fewer threads (--threads)",
                        wait_policy);
  return text;
}

HostLoad current_host_load(int threads, int local_ranks) {
  HostLoad load;
  load.cores = usable_cores();
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  load.host_cores = int(std::max(1L, online));
  if (load.cores.cgroup_quota > 0) load.host_cores = std::min(load.host_cores, load.cores.cgroup_quota);
  load.host_cores = std::max(load.host_cores, load.cores.count);
  load.threads = threads;
  load.local_ranks = local_ranks;
  load.others = other_registered_runs();
  return load;
}

}  // namespace trapdem
