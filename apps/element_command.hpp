#pragma once
// `trapdem element`: the virtual element test (biaxial or triaxial) of a run configuration's
// particles and contact law; writes element.csv, element.json and element.png (docs/element.md).
#include <string>
#include <vector>

namespace trapdem::app {

struct ElementOptions {
  std::string config_file;              // a run configuration (TOML), or empty
  std::string preset;                   // a preset name, or empty (neither: the demo preset)
  std::string test;                     // "biaxial" or "triaxial"; empty: element.test (default biaxial)
  std::vector<double> confining;        // Pa; empty: element.confining (default 50 kPa)
  std::string out_dir;                  // empty: ./trapdem-out/element-<name>
  std::vector<std::string> overrides;   // "key.path=value", e.g. element.particles=2000
  int threads = 0;                      // 0: numerics.threads, else all cores
  bool quiet = false;
};

// Returns the exit code; throws InputError / SimulationError / FileError on failure.
int run_element(const ElementOptions& options);

}  // namespace trapdem::app
