#pragma once
// What this host can give a run, and what the other trapdem runs on it already take (issue 41):
// research groups share workstations, and a run with more threads x ranks than free cores, or two
// runs side by side, slows 3-400x (OpenMP threads and MPI ranks spin while they wait) without a
// word. A run finds its cores (its affinity mask and cgroup v2 quota), registers itself in the
// host's run registry, and reads the others' registrations there.
//
// The registry: one file per running trapdem process, <registry>/run-<pid>, holding its thread count
// and what it runs, with an exclusive flock(2) held for the process's life (as a run folder's
// run.lock): a file whose lock can be taken belongs to a process that ended, however it ended, and
// is removed by whoever finds it. The registry is $TRAPDEM_RUN_REGISTRY when set ("none": no
// registry, nothing registered or read; the test suite's setting, so that its tests do not see
// each other), else /dev/shm/trapdem-runs-<uid> (a tmpfs: nothing of it outlives a reboot), else
// <temporary directory>/.trapdem-runs-<uid>. Only this user's runs are seen.
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem {

// The cores this process may run on: the CPUs of its affinity mask (sched_getaffinity), lowered to
// the cgroup v2 CPU quota (cpu.max "quota period", rounded up) where one is set.
struct UsableCores {
  int count = 1;
  int affinity = 1;   // CPUs in the affinity mask
  int cgroup_quota = 0;  // ceil(quota / period); 0: no quota
  std::string describe() const;  // "2 cores (affinity mask 2, no cgroup quota)"
};
UsableCores usable_cores();

// The cgroup v2 quota in `cpu_max` text ("200000 100000" -> 2, "150000 100000" -> 2, "max 100000"
// -> 0), 0 when there is none or the text is not that format.
int cgroup_quota_cores(const std::string& cpu_max);

// Another trapdem process registered on this host.
struct RegisteredRun {
  int pid = 0;
  int threads = 0;
  std::string what;  // e.g. the run folder
};

std::filesystem::path run_registry_dir();  // empty: none

// This process's registration, held while it lives (the file is removed when it goes).
class RunRegistration {
 public:
  // Registers this process with its `threads` and `what` (one line each). A registry that cannot
  // be written is not an error: the run goes on without (nothing is registered; others do not see it).
  RunRegistration(int threads, const std::string& what);
  ~RunRegistration();
  RunRegistration(const RunRegistration&) = delete;
  RunRegistration& operator=(const RunRegistration&) = delete;
  bool registered() const { return fd_ >= 0; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// The live registrations of the registry other than this process's (stale ones are removed).
std::vector<RegisteredRun> other_registered_runs();

// The load this run puts on the host with the others'. Oversubscribed when this process has more
// threads than its own usable cores (mpirun binds each rank to one core by default), or when the
// threads of every registered run (this one's `threads` x `local_ranks` among them) exceed the
// host's cores.
struct HostLoad {
  UsableCores cores;  // this process's
  int host_cores = 1;  // the host's online CPUs, lowered to the cgroup quota
  int threads = 1;      // this run's threads per process
  int local_ranks = 1;  // this run's processes on this host
  std::vector<RegisteredRun> others;  // other trapdem processes (sibling ranks excluded by the caller)
  int total_threads() const;
  bool process_oversubscribed() const { return threads > cores.count; }
  bool host_oversubscribed() const { return total_threads() > host_cores; }
  bool oversubscribed() const { return process_oversubscribed() || host_oversubscribed(); }
  // The warning's text (empty when not oversubscribed): what was found, what it costs, and how
  // this run's threads wait under `wait_policy` (OMP_WAIT_POLICY's value, "" when not set);
  // `restart_failed`: the program tried to re-execute itself with passive waits and could not
  // (else, with the policy unset, the host was not crowded when it started: the others came later).
  std::string warning(const std::string& wait_policy, bool restart_failed = false) const;
};

// This process's view: its usable cores, the host's, and the others registered (all of them: the
// caller removes its sibling ranks).
HostLoad current_host_load(int threads, int local_ranks);

}  // namespace trapdem
