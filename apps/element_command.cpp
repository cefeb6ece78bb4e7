#include "element_command.hpp"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "run_command.hpp"
#include "study/element_folder.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

int run_element(const ElementOptions& o) {
  if (!o.config_file.empty() && !o.preset.empty()) throw InputError("give either a configuration file or --preset, not both");
  ElementFolderOptions f;
  f.config_file = !o.config_file.empty() ? fs::path(o.config_file) : preset_path(o.preset.empty() ? "demo" : o.preset);
  // The options go through the configuration as overrides, so that they are checked and recorded
  // (resolved.toml) as the file's own keys are.
  if (!o.test.empty()) f.overrides.push_back("element.test=" + o.test);
  if (!o.confining.empty()) {
    std::string list;
    for (double p : o.confining) list += fmt::format("{}{}", list.empty() ? "" : ", ", p);
    f.overrides.push_back("element.confining=[" + list + "]");
  }
  f.overrides.insert(f.overrides.end(), o.overrides.begin(), o.overrides.end());
  f.out_dir = o.out_dir;
  f.threads = o.threads;
  if (!o.quiet)
    f.echo = [](const std::string& line) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    };
  run_element_in_folder(f);
  return 0;
}

}  // namespace trapdem::app
