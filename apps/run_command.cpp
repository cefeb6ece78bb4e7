#include "run_command.hpp"

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/presets.hpp"
#include "installed_presets.hpp"
#ifdef TRAPDEM_HAVE_MPI
#include "parallel/mpi_run.hpp"
#endif

namespace fs = std::filesystem;

namespace trapdem::app {

fs::path preset_directory() {
  if (const char* env = std::getenv("TRAPDEM_PRESETS")) return env;
  if (const auto installed = installed_preset_directory()) return *installed;
  return TRAPDEM_PRESET_DIR;
}

fs::path preset_path(const std::string& name) { return preset_file(preset_directory(), name); }

int list_presets() {
  for (const PresetEntry& p : trapdem::list_presets(preset_directory()))
    fmt::print("{:<18} {}\n", p.name, p.description);
  return 0;
}

// Whether an MPI launcher started this process as one of several ranks (Open MPI's mpirun sets
// OMPI_COMM_WORLD_SIZE; MPICH's mpiexec and Slurm's srun with PMI set PMI_SIZE).
int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  return 1;
}

int run_experiment(const RunOptions& o) {
  FolderRunOptions run;
  if (!o.config_file.empty() && !o.preset.empty())
    throw InputError("give either a configuration file or --preset, not both");
  if (!o.resume_dir.empty()) {
    run.resume_dir = o.resume_dir;
    run.config_file = !o.config_file.empty() ? fs::path(o.config_file) : !o.preset.empty() ? preset_path(o.preset) : fs::path();
    if (!o.out_dir.empty()) throw InputError(fmt::format("--resume {} writes into that folder: give no --out", o.resume_dir));
  } else {
    run.config_file = !o.config_file.empty() ? fs::path(o.config_file) : preset_path(o.preset.empty() ? "demo" : o.preset);
    run.out_dir = o.out_dir;
  }
  run.overrides = o.overrides;
  run.allowed_changes = o.allowed_changes;
  run.threads = o.threads;
  run.quiet = o.quiet;
  run.stop_after_seconds = o.stop_after_seconds;
  run.stop_at_step = o.stop_at_step;
  if (launched_ranks() > 1) {
#ifdef TRAPDEM_HAVE_MPI
    return run_in_folder_on_ranks(run);
#else
    throw InputError(fmt::format("started as {} ranks (mpirun), but this trapdem was built without MPI: each would run "
                                 "the whole experiment into the same folder; build with -DTRAPDEM_MPI=ON (Open MPI: "
                                 "scripts/install-deps) or run one process",
                                 launched_ranks()));
#endif
  }
  return run_in_folder(run) ? kExitDone : kExitInterrupted;
}

}  // namespace trapdem::app
