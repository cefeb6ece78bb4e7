#include "study_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "io/text_file.hpp"
#include "run_command.hpp"
#include "study/study_runner.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

int run_study(const StudyOptions& o) {
  const StudyDefinition study = load_study(o.file);
  const StudyScale& scale = study.scale(o.scale.empty() ? study.default_scale : o.scale);
  const fs::path out = o.out.empty() ? fs::path("trapdem-out") / (study.name + "-" + scale.name) : fs::path(o.out);
  if (o.report_only) {
    if (!holds_study(out)) throw InputError(fmt::format("--report-only: {} holds no study", out.string()));
    claim_study_folder(study, scale, out);
  } else if (!run_study_in_folder(study, scale, out, StudyRunSettings{preset_directory(), o.threads, o.quiet})) {
    return 130;
  }
  const fs::path page = write_study_outputs(study, scale, out, o.quiet, preset_directory());
  log_study_line(out, fmt::format("report: {}", page.string()), o.quiet);
  if (!o.quiet) {
    const Json summary = Json::parse(read_text_file(page.parent_path() / "summary.json"));
    for (std::size_t k = 0; k < summary["findings"].size(); ++k)
      fmt::print("  - {}\n", summary["findings"][k].as_string());
  }
  return 0;
}

}  // namespace trapdem::app
