#include "core/wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "core/host_load.hpp"

namespace trapdem {

namespace {

// The commands that run the engine (the others finish in seconds and use one thread mostly).
bool runs_the_engine(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.empty() || word[0] == '-') continue;
    return word == "run" || word == "study" || word == "element" || word == "calibrate" || word == "showcase";
  }
  return false;
}

// --threads N or --threads=N in argv; 0 when absent or not a number (every usable core).
int threads_in_arguments(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    const char* value = nullptr;
    if (word == "--threads" && i + 1 < argc)
      value = argv[i + 1];
    else if (word.rfind("--threads=", 0) == 0)
      value = argv[i] + 10;
    if (!value) continue;
    char* end = nullptr;
    const long n = std::strtol(value, &end, 10);
    return end != value && *end == '\0' && n > 0 && n < 1 << 20 ? int(n) : 0;
  }
  return 0;
}

bool restart_failed = false;

}  // namespace

bool passive_restart_failed() { return restart_failed; }

std::string wait_policy() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  return policy ? policy : "";
}

int local_rank_count() {
  const char* size = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (!size) return 1;
  const int n = std::atoi(size);
  return n > 0 ? n : 1;
}

void wait_passively_when_crowded(int argc, char** argv) {
  if (std::getenv("OMP_WAIT_POLICY")) return;  // set by hand (or by this function before the exec)
  if (!runs_the_engine(argc, argv)) return;
  const int asked = threads_in_arguments(argc, argv);
  const int threads = asked > 0 ? asked : usable_cores().count;
  // Registered before the others are read: of two runs started at the same moment, the later to
  // register sees the earlier (either may be first, but not both); a run registers itself anew,
  // under the same name, once its thread count is known (folder_run.cpp).
  static std::optional<RunRegistration> starting;
  starting.emplace(threads, "starting");
  const HostLoad load = current_host_load(threads, local_rank_count());
  if (!load.oversubscribed()) return;
  starting.reset();  // the restarted program registers itself again
  ::setenv("OMP_WAIT_POLICY", "passive", 1);
  ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
  ::execv("/proc/self/exe", argv);  // returns only on failure: the run goes on spinning, and says so
  restart_failed = true;
}

}  // namespace trapdem
