#pragma once
// The error types every module throws, so that the command can tell the user what to fix:
// InputError (the configuration or a command-line value), SimulationError (a run that cannot go
// on), FileError (the disk: a file that cannot be read or written).
#include <stdexcept>

namespace trapdem {

// A run that cannot go on: unstable integration, particles escaping, impossible input.
// The message names what failed, where, and the likely cause.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Input that breaks a documented rule (configuration key, file line, parameter range).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file that cannot be written or read as expected: unwritable folder, full disk, missing or
// damaged file. The message names the path (and the dataset or key inside it) and the cause.
// Separate from InputError so that a caller can tell "fix your configuration" from "fix your disk".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trapdem
