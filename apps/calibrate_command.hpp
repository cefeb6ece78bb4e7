#pragma once
// `trapdem calibrate BASE.toml --vary KEY=V1,V2,... --target PIV_DIR --at 10mm`: the calibration of
// study/calibration.hpp on the command line, its ranked table printed; with `--submit slurm` the
// grid goes to a Slurm cluster as a job array and the ranking to a job after it, `--status` says
// where each case stands.
#include "study/calibration.hpp"
#include "study_command.hpp"

namespace trapdem::app {

struct CalibrateCommand {
  CalibrateOptions calibrate;
  SubmitOptions submit;
  bool status = false;        // no running: where each case stands
};

int run_calibrate(const CalibrateCommand& command);

}  // namespace trapdem::app
