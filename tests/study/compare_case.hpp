#pragma once
// A DEM run folder and a PIV output folder of the same synthetic settlement field, the PIV one
// offset by a known amount, for the comparison tests (run_comparison_test, compare_command_test).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "study/run_comparison.hpp"
#include "../scratch_dir.hpp"
#include "synthetic_piv.hpp"
#include "synthetic_run.hpp"

namespace trapdem::test {

// A linear settlement field (exact under linear interpolation on any triangulation): w < 0 down.
inline double settlement_w(Point2 p, double delta) { return -delta * (0.8 - 2.0 * (p.z - 0.02) + 1.5 * (p.x - 0.1)); }

struct CompareCase {
  ScratchDir root;  // holds both; removed with the case
  std::filesystem::path run, piv;

  // The options comparing the two at the last displacement (10 mm).
  CompareOptions options() const {
    CompareOptions o;
    o.dem_dir = run.string();
    o.piv_dir = piv.string();
    o.at = "10mm";
    return o;
  }
};

// In a scratch folder PREFIX-XXXXXX: run/ and piv/ at trapdoor displacements 0, 5 and 10 mm, the
// PIV field `offset_m` (m) higher everywhere.
inline CompareCase make_compare_case(const std::string& prefix, double offset_m) {
  ScratchDir root(prefix);
  const std::vector<double> deltas{0.0, 0.005, 0.01};
  make_synthetic_run(root / "run", deltas, [](Point2 p, double delta) { return Point2{0.0, settlement_w(p, delta)}; });
  write_synthetic_piv(root / "piv", deltas, [&](Point2 p, double delta) { return settlement_w(p, delta) + offset_m; });
  const std::filesystem::path run = root / "run", piv = root / "piv";
  return {std::move(root), run, piv};
}

}  // namespace trapdem::test
