#pragma once
// The exit codes of every trapdem command and program (README, "Exit codes"): what scripts, Slurm
// arrays and study runners branch on. One table, here.
#include <exception>

#include "core/errors.hpp"

namespace trapdem {

inline constexpr int kExitDone = 0;         // finished
inline constexpr int kExitUnexpected = 1;   // an error of no kind below (a bug: please report it)
inline constexpr int kExitInputError = 2;   // bad input: the command line, an input file, a configuration
inline constexpr int kExitRunStopped = 3;   // a run stopped by the physics guard (SimulationError)
inline constexpr int kExitFileError = 4;    // a file or disk error (FileError): missing, damaged, full
inline constexpr int kExitInterrupted = 130;  // stopped by SIGINT/SIGTERM or a stop rule, with its checkpoint: resume it

// The code of an error thrown out of a command.
inline int exit_code_of(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e)) return kExitInputError;
  if (dynamic_cast<const SimulationError*>(&e)) return kExitRunStopped;
  if (dynamic_cast<const FileError*>(&e)) return kExitFileError;
  return kExitUnexpected;
}

}  // namespace trapdem
