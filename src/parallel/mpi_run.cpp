#include "parallel/mpi_run.hpp"

#include <mpi.h>

#include <cstdio>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "parallel/failure_agreement.hpp"
#include "parallel/mpi_run_ranks.hpp"

namespace trapdem {

int run_in_folder_on_ranks(FolderRunOptions options) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = 0;  // OpenMP threads inside a rank make no MPI call: the main thread does them all
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  }
  struct Finalise {
    bool owned;
    ~Finalise() {
      if (owned) MPI_Finalize();
    }
  } finalise{!initialised};
  MpiRunRanks ranks(MPI_COMM_WORLD);
  options.ranks = &ranks;
  try {
    return run_in_folder(options) ? kExitDone : kExitInterrupted;
  } catch (const std::exception& e) {
    if (!failure_was_agreed()) {
      fmt::print(stderr, "trapdem: rank {} of {} stops every rank: {}\n", ranks.rank(), ranks.ranks(), e.what());
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, exit_code_of(e));
    }
    if (ranks.root()) throw;
    return exit_code_of(e);
  }
}

}  // namespace trapdem
