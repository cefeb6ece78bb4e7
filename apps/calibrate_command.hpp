#pragma once
// `trapdem calibrate BASE.toml --vary KEY=V1,V2,... --target PIV_DIR --at 10mm`: the calibration of
// study/calibration.hpp on the command line, its ranked table printed.
#include "study/calibration.hpp"

namespace trapdem::app {

int run_calibrate(const CalibrateOptions& options);

}  // namespace trapdem::app
