// The host's cores and run registry (src/core/host_load.hpp, issue 41): the cgroup quota as the
// kernel writes it, a live run seen by another process and a killed one's registration removed,
// and the oversubscription warning's arithmetic.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../io/io_test_support.hpp"
#include <fmt/format.h>

#include "core/host_load.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

namespace {

// The registry of this test only: TRAPDEM_RUN_REGISTRY set for its life, restored after.
class PrivateRegistry {
 public:
  PrivateRegistry() {
    const char* before = std::getenv("TRAPDEM_RUN_REGISTRY");
    if (before) before_ = before;
    had_ = before != nullptr;
    ::setenv("TRAPDEM_RUN_REGISTRY", (scratch_ / "registry").c_str(), 1);
  }
  ~PrivateRegistry() {
    if (had_)
      ::setenv("TRAPDEM_RUN_REGISTRY", before_.c_str(), 1);
    else
      ::unsetenv("TRAPDEM_RUN_REGISTRY");
  }
  fs::path dir() const { return scratch_ / "registry"; }

 private:
  io_testing::ScratchDir scratch_{"trapdem-host-load"};
  std::string before_;
  bool had_ = false;
};

// A child process that registers a run with `threads` and waits until it is killed; returns its
// pid once it is registered (it writes a byte to a pipe then).
pid_t registered_child(int threads, const std::string& what) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(ready[0]);
    const RunRegistration registration(threads, what);
    const char byte = registration.registered() ? 'y' : 'n';
    [[maybe_unused]] const ssize_t n = ::write(ready[1], &byte, 1);
    for (;;) ::pause();
  }
  ::close(ready[1]);
  char byte = 0;
  const ssize_t n = ::read(ready[0], &byte, 1);
  ::close(ready[0]);
  return n == 1 && byte == 'y' ? pid : -1;
}

void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

}  // namespace

TEST(HostLoad, CgroupQuotaAsTheKernelWritesIt) {
  EXPECT_EQ(cgroup_quota_cores("max 100000\n"), 0);        // no quota
  EXPECT_EQ(cgroup_quota_cores("200000 100000\n"), 2);     // two cores' time per period
  EXPECT_EQ(cgroup_quota_cores("150000 100000"), 2);       // 1.5 cores: a second thread still runs
  EXPECT_EQ(cgroup_quota_cores("50000 100000"), 1);
  EXPECT_EQ(cgroup_quota_cores(""), 0);
  EXPECT_EQ(cgroup_quota_cores("garbage"), 0);
  EXPECT_EQ(cgroup_quota_cores("12x 100000"), 0);
  EXPECT_EQ(cgroup_quota_cores("100000 0"), 0);
}

TEST(HostLoad, UsableCoresWithinTheMachine) {
  const UsableCores cores = usable_cores();
  EXPECT_GE(cores.count, 1);
  EXPECT_LE(cores.count, cores.affinity);
  EXPECT_LE(cores.affinity, int(sysconf(_SC_NPROCESSORS_CONF)));
  if (cores.cgroup_quota > 0) {
    EXPECT_LE(cores.count, cores.cgroup_quota);
  }
  EXPECT_NE(cores.describe().find("affinity mask"), std::string::npos) << cores.describe();
}

TEST(HostLoad, AnotherProcessesRunIsSeenAndAKilledOnesRegistrationRemoved) {
  const PrivateRegistry registry;
  EXPECT_TRUE(other_registered_runs().empty());
  const pid_t child = registered_child(3, "/somewhere/trapdem-out/demo");
  ASSERT_GT(child, 0);
  {
    const RunRegistration own(2, "this test");
    ASSERT_TRUE(own.registered());
    const auto others = other_registered_runs();  // this process's own registration is not listed
    ASSERT_EQ(others.size(), 1u);
    EXPECT_EQ(others[0].pid, child);
    EXPECT_EQ(others[0].threads, 3);
    EXPECT_EQ(others[0].what, "/somewhere/trapdem-out/demo");
  }
  EXPECT_FALSE(fs::exists(registry.dir() / ("run-" + std::to_string(::getpid()))));  // removed at its end
  kill_and_reap(child);  // SIGKILL: no destructor ran, its file stays, but its lock went with it
  ASSERT_TRUE(fs::exists(registry.dir() / ("run-" + std::to_string(child))));
  EXPECT_TRUE(other_registered_runs().empty());
  EXPECT_FALSE(fs::exists(registry.dir() / ("run-" + std::to_string(child))));  // the stale file removed
}

TEST(HostLoad, NoRegistryWhenTurnedOff) {
  const PrivateRegistry registry;
  ::setenv("TRAPDEM_RUN_REGISTRY", "none", 1);
  const RunRegistration own(2, "x");
  EXPECT_FALSE(own.registered());
  EXPECT_TRUE(other_registered_runs().empty());
  EXPECT_FALSE(fs::exists(registry.dir()));
}

TEST(HostLoad, WarningWhenThreadsExceedTheCores) {
  HostLoad load;
  load.cores.count = 2;
  load.cores.affinity = 2;
  load.host_cores = 2;
  load.threads = 2;
  EXPECT_FALSE(load.oversubscribed());  // 2 threads on 2 cores: what a run should be
  EXPECT_EQ(load.warning("passive"), "");
  load.others.push_back({4242, 2, "/x/run-b"});
  EXPECT_EQ(load.total_threads(), 4);
  EXPECT_TRUE(load.oversubscribed());
  const std::string passive = load.warning("PASSIVE");
  EXPECT_NE(passive.find("4 threads of trapdem runs on the host's 2 cores"), std::string::npos) << passive;
  EXPECT_NE(passive.find("pid 4242 2 threads (/x/run-b)"), std::string::npos) << passive;
  EXPECT_NE(passive.find("wait passively"), std::string::npos) << passive;
  EXPECT_NE(load.warning("active").find("OMP_WAIT_POLICY=active was set by hand"), std::string::npos);
  EXPECT_NE(load.warning("", true).find("could not restart itself"), std::string::npos);
  EXPECT_NE(load.warning("").find("the host was not crowded when it started"), std::string::npos);
  HostLoad ranks;
  ranks.cores.count = 1;  // mpirun binds each rank to a core
  ranks.host_cores = 2;
  ranks.threads = 2;
  ranks.local_ranks = 2;  // 2 ranks x 2 threads on 2 cores
  EXPECT_EQ(ranks.total_threads(), 4);
  EXPECT_TRUE(ranks.process_oversubscribed());
  EXPECT_TRUE(ranks.host_oversubscribed());
  const std::string both = ranks.warning("passive");
  EXPECT_NE(both.find("this process runs 2 threads on its 1 core"), std::string::npos) << both;
  EXPECT_NE(both.find("x 2 ranks here"), std::string::npos) << both;
  HostLoad alone;  // one run of as many threads as cores: no warning
  alone.cores.count = 2;
  alone.host_cores = 2;
  alone.threads = 2;
  EXPECT_FALSE(alone.oversubscribed());
}

namespace {

// `trapdem run` of a shortened tiny preset with 1 thread beside a registered run of 64 threads,
// OMP_WAIT_POLICY as `policy` ("" unset); its run.log.
std::string run_log_beside_a_crowd(const std::string& policy) {
  const PrivateRegistry registry;
  const pid_t crowd = registered_child(64, "a crowd");
  if (crowd <= 0) return "the registered child did not start";
  io_testing::ScratchDir scratch("trapdem-host-load-run");
  const std::string command = fmt::format(
      "env {} TRAPDEM_RUN_REGISTRY='{}' '{}' run --preset tiny --out '{}' --threads 1 --quiet "
      "--set pluviation.fill_height=0.01 --set settling.max_time=0.01 --set spin_up.ramp_time=0.005 "
      "--set trapdoor.travel=0.0005 --set 'output.snapshot_displacements=[0.0]' > '{}' 2>&1",
      policy.empty() ? std::string("-u OMP_WAIT_POLICY") : "OMP_WAIT_POLICY=" + policy, registry.dir().string(),
      TRAPDEM_EXECUTABLE, (scratch / "run").string(), (scratch / "terminal.txt").string());
  const int status = std::system(command.c_str());
  kill_and_reap(crowd);
  if (status != 0) return "trapdem run failed: " + io_testing::read_all(scratch / "terminal.txt");
  return io_testing::read_all(scratch / "run" / "run.log") + "\n--- terminal:\n" +
         io_testing::read_all(scratch / "terminal.txt");
}

}  // namespace

// Beside another run, a run warns in run.log and on the terminal (also under --quiet) and its
// threads wait passively: the program re-executed itself with OMP_WAIT_POLICY=passive.
TEST(HostLoad, RunBesideAnotherWarnsAndWaitsPassively) {
  const std::string log = run_log_beside_a_crowd("");
  EXPECT_NE(log.find("65 threads of trapdem runs on the host"), std::string::npos) << log;
  EXPECT_NE(log.find("64 threads (a crowd)"), std::string::npos) << log;
  EXPECT_NE(log.find("wait passively"), std::string::npos) << log;
  const auto terminal = log.find("--- terminal:");
  EXPECT_NE(log.find("oversubscribed", terminal), std::string::npos) << log;
}

// Two runs started at the same moment, each with as many threads as this process has cores: the
// later to register sees the earlier, so at least one warns and waits passively. The other may
// warn too, when it meets the first registered at its run's start: it found the host free when it
// started, and says so (its threads spin; how they wait is fixed at the start).
TEST(HostLoad, TwoRunsStartedTogetherSeeEachOther) {
  const PrivateRegistry registry;
  io_testing::ScratchDir scratch("trapdem-host-load-pair");
  const int cores = usable_cores().count;
  const auto command = [&](const std::string& name) {
    return fmt::format("env -u OMP_WAIT_POLICY TRAPDEM_RUN_REGISTRY='{}' '{}' run --preset tiny --out '{}' --threads {} "
                       "--quiet --set pluviation.fill_height=0.01 --set settling.max_time=0.01 --set "
                       "spin_up.ramp_time=0.005 --set trapdoor.travel=0.0005 --set 'output.snapshot_displacements=[0.0]' "
                       "> /dev/null 2>&1",
                       registry.dir().string(), TRAPDEM_EXECUTABLE, (scratch / name).string(), cores);
  };
  const std::string both = "(" + command("a") + ") & (" + command("b") + ") & wait";
  ASSERT_EQ(std::system(("bash -c \"" + both + "\"").c_str()), 0);
  int passive = 0;
  for (const char* name : {"a", "b"}) {
    const std::string log = io_testing::read_all(scratch / name / "run.log");
    if (log.find("oversubscribed") == std::string::npos) continue;
    const bool waits_passively = log.find("wait passively") != std::string::npos;
    passive += waits_passively;
    if (!waits_passively) {
      EXPECT_NE(log.find("the host was not crowded when it started"), std::string::npos) << log;
    }
  }
  EXPECT_GE(passive, 1);
}

// OMP_WAIT_POLICY set by hand is kept, and the warning says what it costs.
TEST(HostLoad, RunBesideAnotherKeepsAWaitPolicySetByHand) {
  const std::string log = run_log_beside_a_crowd("active");
  EXPECT_NE(log.find("this host oversubscribed"), std::string::npos) << log;
  EXPECT_NE(log.find("OMP_WAIT_POLICY=active was set by hand"), std::string::npos) << log;
}
