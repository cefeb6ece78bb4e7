#pragma once
#include <stdexcept>

namespace trapdem {

// A file that cannot be written or read as expected: unwritable folder, full disk, missing or
// damaged file. The message names the path (and the dataset or key inside it) and the cause.
// Separate from InputError so that a caller can tell "fix your configuration" from "fix your disk".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trapdem
