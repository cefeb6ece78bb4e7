#pragma once
// `trapdem compare DEM_DIR PIV_DIR --at 10mm`: the comparison of study/run_comparison.hpp, printed
// as text or JSON, and its overlay figure.
#include "study/run_comparison.hpp"

namespace trapdem::app {

// The whole command; returns the exit code.
int run_compare(const CompareOptions& options);

}  // namespace trapdem::app
