#pragma once
// A run folder with only what the sinkhole estimate of a DEM run reads (resolved.toml and
// analysis/metrics.json), for sinkhole_run_test and sinkhole_command_test.
#include <filesystem>
#include <fstream>
#include <string>

#include "../scratch_dir.hpp"

namespace trapdem::test {

// tan 30 = 1/sqrt(3) = 0.5773502692
constexpr double kTan30 = 0.5773502691896258;

// A run folder with only what `sinkhole --from` reads: N = 40, B = 50 mm, fill 150 mm, a surface zone
// 200 mm wide and bands at 10 and 20 degrees; a scratch folder trapdem-sinkhole-NAME-XXXXXX.
inline ScratchDir sinkhole_run_folder(const std::string& name, bool with_surface_height = true,
                                      const std::string& warning = "") {
  ScratchDir dir("trapdem-sinkhole-" + name);
  std::filesystem::create_directories(dir / "analysis");
  std::ofstream(dir / "resolved.toml") << "name = \"tiny\"\n[spin_up]\ng_level = 40.0\n[trapdoor]\nwidth = 0.05\n"
                                          "[pluviation]\nfill_height = 0.15\n";
  std::ofstream(dir / "analysis" / "metrics.json")
      << "{\"trapdoor\": {\"width_m\": 0.05, \"travel_m\": 0.02},\n"
         " \"shear_bands\": {\"left\": {\"angle_deg\": 10.0}, \"right\": {\"angle_deg\": 20.0}},\n"
         " \"zone_of_influence\": {\"settlement_fraction\": 0.05, "
      << (with_surface_height ? "\"surface_height_m\": 0.16, " : "\"surface_height_m\": null, ")
      << "\"surface_width_m\": 0.2}"
      << (warning.empty() ? std::string() : ", \"warnings\": [\"" + warning + "\"]") << "}\n";
  return dir;
}

}  // namespace trapdem::test
