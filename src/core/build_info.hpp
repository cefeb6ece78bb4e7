#pragma once
// The code and the machine a result came from: run.json and run.log name both, so that a published
// run can be traced to its commit and its timings to a CPU (a referee recomputes, a user reruns).
#include <string>
#include <string_view>

namespace trapdem {

struct BuildInfo {
  std::string_view commit;  // the full hash of the checkout's HEAD when built; empty: not a git checkout
  bool modified = false;    // tracked files differed from that commit when built
};

// Written at build time (cmake/write_build_info.cmake into the build tree).
const BuildInfo& build_info();

// "7a62e4e1c2d3" (12 characters), "7a62e4e1c2d3 with uncommitted changes", or "unknown (not built
// from a git checkout)".
std::string describe_build(const BuildInfo& info = build_info());

// This host's processor as /proc/cpuinfo names it, with what tells one generation from another:
// "AMD EPYC (family 26, model 2), AVX-512" ("unknown processor" where /proc/cpuinfo is not there).
std::string describe_cpu();
// The same from a /proc/cpuinfo text (its first processor's block), for tests.
std::string describe_cpu(std::string_view cpuinfo);

}  // namespace trapdem
