#pragma once
// The error types every module throws, so that the command can tell the user what to fix:
// InputError (the configuration or a command-line value), SimulationError (a run that cannot go
// on), FileError (the disk: a file that cannot be read or written).
#include <stdexcept>

// SimulationError and InputError are defined with the engine until its files include this header.
#include "dem/errors.hpp"

namespace trapdem {

// A file that cannot be written or read as expected: unwritable folder, full disk, missing or
// damaged file. The message names the path (and the dataset or key inside it) and the cause.
// Separate from InputError so that a caller can tell "fix your configuration" from "fix your disk".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trapdem
