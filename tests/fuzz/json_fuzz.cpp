// The JSON reader (run.json, metrics.json, study.json, summary.json read back). A document that
// parses must write out and parse again to the same text.
#include <cstdio>
#include <cstdlib>

#include "core/json.hpp"
#include "fuzz_target.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string written;
  fuzzing::expecting_clear_errors([&] { written = Json::parse(fuzzing::as_text(data, size), "fuzz.json").dump(); });
  if (written.empty()) return 0;
  try {
    const std::string again = Json::parse(written, "written.json").dump();
    if (again != written) {
      std::fprintf(stderr, "JSON written and read back differs:\n%s\n%s\n", written.c_str(), again.c_str());
      std::abort();
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "JSON written does not parse again: %s\n%s\n", e.what(), written.c_str());
    std::abort();
  }
  return 0;
}
