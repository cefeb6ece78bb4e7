#include "core/wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "core/host_load.hpp"

namespace trapdem {

namespace {

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

}  // namespace

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
  const int asked = threads_in_arguments(argc, argv);
  const HostLoad load = current_host_load(asked > 0 ? asked : usable_cores().count, local_rank_count());
  if (!load.oversubscribed()) return;
  ::setenv("OMP_WAIT_POLICY", "passive", 1);
  ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
  ::execv("/proc/self/exe", argv);  // returns only on failure: the run goes on spinning, and says so
}

}  // namespace trapdem
