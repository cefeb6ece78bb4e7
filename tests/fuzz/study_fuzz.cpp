// A study file (`trapdem study FILE`, docs/study.md) through load_study, which takes a path: the
// input is written to a file first. Then every case's recipe at every scale, as the runner asks.
#include "fuzz_target.hpp"
#include "study/study_definition.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzzing::input_file(fuzzing::as_text(data, size), "study.toml");
  fuzzing::expecting_clear_errors([&] {
    const StudyDefinition study = load_study(file);
    for (const StudyScale& scale : study.scales) {
      for (const StudyCase& c : study.cases) {
        case_recipe(c, scale);
        case_replicates(study, c, scale);
      }
    }
    if (!study.default_scale.empty()) study.scale(study.default_scale);
  });
  return 0;
}
