#pragma once
// The virtual element test of a run configuration into a folder: what `trapdem element` does
// (docs/element.md), as a library call for any front end. Writes resolved.toml, element.log,
// element.csv, element.json and element.png.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "experiment/element_output.hpp"
#include "experiment/element_test.hpp"

namespace trapdem {

struct ElementFolderOptions {
  std::filesystem::path config_file;   // a run configuration (TOML) with its [element] table
  std::vector<std::string> overrides;  // "key.path=value" on top, checked and recorded as the file's keys
  std::filesystem::path out_dir;       // empty: ./trapdem-out/element-<name>
  int threads = 0;                     // 0: numerics.threads, else all cores
  std::function<void(const std::string&)> echo;  // each element.log line as it is written (optional)
};

struct ElementFolderResult {
  std::filesystem::path out;
  ElementResult result;
  std::vector<ElementAngles> angles;  // per confining stress
};

// Throws InputError for a bad configuration, SimulationError, FileError.
ElementFolderResult run_element_in_folder(const ElementFolderOptions& options);

}  // namespace trapdem
