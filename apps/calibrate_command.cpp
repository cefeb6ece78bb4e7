#include "calibrate_command.hpp"

#include <fmt/format.h>

namespace trapdem::app {

int run_calibrate(const CalibrateOptions& o) {
  const Calibration c = calibrate(o);
  if (!c.complete) {
    fmt::print("calibration interrupted (checkpoint written); run the same command again to carry on\n");
    return 130;
  }
  fmt::print("calibration against {} at {}: {} cases, ranked by RMS(w_DEM - w_PIV)/δ\n", o.target, o.at,
             c.ranked.size());
  std::string head = fmt::format("{:>4}  ", "rank");
  for (const VariedKey& k : c.keys) head += fmt::format("{:>24}  ", k.key);
  fmt::print("{}{:>10}  {:>10}  {:>8}\n", head, "error %", "bias %", "covered");
  for (std::size_t r = 0; r < c.ranked.size(); ++r) {
    std::string line = fmt::format("{:>4}  ", r + 1);
    for (const std::string& v : c.ranked[r].values) line += fmt::format("{:>24}  ", v);
    fmt::print("{}{:>10.3f}  {:>10.3f}  {:>7.0f}%\n", line, 100.0 * c.ranked[r].error, 100.0 * c.ranked[r].bias,
               100.0 * c.ranked[r].coverage);
  }
  fmt::print("written in {}: calibration.csv, best.toml (run it with `trapdem run {}`), error_surface.png, "
             "compare_best.png, report/index.html\n", c.out.string(), (c.out / "best.toml").string());
  return 0;
}

}  // namespace trapdem::app
