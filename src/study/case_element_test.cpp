#include "study/case_element_test.hpp"

#include <omp.h>

#include <fstream>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/thread_scope.hpp"
#include "core/json.hpp"
#include "experiment/element_output.hpp"
#include "experiment/element_test.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

fs::path element_json_file(const fs::path& dir) { return dir / "element.json"; }
fs::path element_resolved_file(const fs::path& dir) { return dir / "resolved.toml"; }

}  // namespace

CaseElementTest case_element_test(const StudyCase& c, const fs::path& base, const ConfigRecipe& recipe,
                                  const StudyReportSettings& report) {
  try {
    Config config = Config::load_file(base.string());
    config.apply_overrides(recipe.overrides);
    config.apply_overrides(report.element_overrides);
    CaseElementTest test;
    test.setup = read_element_setup(config);
    test.resolved = config.resolved_toml();
    return test;
  } catch (const InputError& e) {
    throw InputError(fmt::format("case '{}', element test ([report] element_test, [report.element]): {}", c.name,
                                 e.what()));
  }
}

bool element_test_finished(const CaseElementTest& test, const fs::path& dir) {
  const fs::path resolved = element_resolved_file(dir);
  return fs::exists(element_json_file(dir)) && fs::exists(resolved) && read_text_file(resolved) == test.resolved;
}

void run_case_element_test(const CaseElementTest& test, const fs::path& dir, int threads) {  // A test of another configuration, or one stopped half way: run it afresh (it is short beside
  // the trapdoor runs, and nothing of it can be resumed).
  if (fs::exists(dir)) fs::remove_all(dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(fmt::format("cannot create the element-test folder {}: {}", dir.string(), ec.message()));

  std::ofstream log_file(dir / "element.log");
  if (!log_file) throw FileError(fmt::format("cannot open {} for writing", (dir / "element.log").string()));
  const ElementLog log = [&](const std::string& line) {
    log_file << line << '\n';
    log_file.flush();
  };
  {
    const ThreadScope scope(threads > 0 ? threads : test.setup.threads);
    const ElementResult result = run_element_test(test.setup, log);
    write_element_files(dir, result);
  }
  // Last: its presence with element.json marks the test finished for this configuration.
  write_text_atomically(element_resolved_file(dir), test.resolved);
}

CaseElementAngles read_case_element_angles(const fs::path& dir) {
  CaseElementAngles a;
  const fs::path file = element_json_file(dir);
  if (!fs::exists(file) || !fs::exists(element_resolved_file(dir))) return a;
  const Json j = Json::parse(read_text_file(file), file.string());
  const Json& angles = json_member_or_null(j, "angles");
  if (angles.type() != Json::Type::array || angles.size() == 0) return a;
  a.confining = json_number_or_nan(angles[0], "confining_Pa");
  a.phi_peak_deg = json_number_or_nan(angles[0], "phi_peak_deg");
  a.phi_cs_deg = json_number_or_nan(angles[0], "phi_cs_deg");
  return a;
}

}  // namespace trapdem
