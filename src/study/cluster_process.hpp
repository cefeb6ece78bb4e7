#pragma once
// A cluster's client command (sbatch, sinfo, scancel) run as a process, its output captured: the
// Slurm submission talks to Slurm through its documented commands only (issue 16), never a shell.
#include <string>
#include <vector>

namespace trapdem {

struct ProcessResult {
  int exit_code = -1;     // the program's exit code; -1 if a signal ended it
  std::string output;     // what it wrote on stdout
  std::string errors;     // what it wrote on stderr
};

// Whether `program` is an executable file in a folder of PATH (or, with a '/', that file).
bool program_on_path(const std::string& program);

// Runs argv[0] (looked up on PATH) with the arguments, waits for it and returns its exit code and
// output. Throws FileError naming the program if it cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv);

}  // namespace trapdem
