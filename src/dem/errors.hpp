#pragma once
#include <stdexcept>
#include <string>

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

}  // namespace trapdem
