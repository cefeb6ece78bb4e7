#pragma once
// A study file written by a test, and the error its loading gives: shared by the study tests.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "study/study_definition.hpp"
#include "../io/io_test_support.hpp"

namespace trapdem::study_test {

// `text` as `name` in a folder of this process's own under the temporary directory.
inline std::filesystem::path write_study(const std::string& name, const std::string& text) {
  static const io_testing::ScratchDir dir("trapdem-study-file");  // removed at the process's exit
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// The InputError message of loading `text` as a study, or "(no error)".
inline std::string error_of(const std::string& text) {
  try {
    load_study(write_study("bad.toml", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace trapdem::study_test
