// The run configuration as `trapdem run` resolves it (folder_run.cpp): a TOML document, the --set
// overrides on top (the input's NUL-separated parts after the first), ExperimentConfig::from (every
// range, cross-key rule and unknown key); then the resolved record, which must read back and
// resolve again to the same record (docs/config.md: a resolved.toml can be run again as it is).
#include <cstdio>
#include <cstdlib>

#include "experiment/experiment_config.hpp"
#include "fuzz_target.hpp"
#include "io/config.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzzing::split_at_nul(fuzzing::as_text(data, size));
  std::string resolved;
  fuzzing::expecting_clear_errors([&] {
    Config config = Config::parse(parts[0], "fuzz.toml");
    config.apply_overrides({parts.begin() + 1, parts.end()});
    ExperimentConfig::from(config);
    resolved = config.resolved_toml();
  });
  if (resolved.empty()) return 0;
  try {
    Config again = Config::parse(resolved, "resolved.toml");
    ExperimentConfig::from(again);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "a resolved configuration does not resolve again: %s\n%s\n", e.what(), resolved.c_str());
    std::abort();
  }
  return 0;
}
