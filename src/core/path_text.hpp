#pragma once
// A file as a page or a note names it. A study's report is published and read on other machines,
// where the absolute path of the machine that ran it means nothing; relative to the study folder
// (cases/rf1/analysis/metrics.json) it names the same file in the published copy.
#include <filesystem>
#include <string>

namespace trapdem {

// `file` relative to `base` where `base` is given and holds it; otherwise `file` as it is.
inline std::string path_from(const std::filesystem::path& file, const std::filesystem::path& base) {
  if (base.empty()) return file.string();
  const std::filesystem::path relative = file.lexically_normal().lexically_relative(base.lexically_normal());
  if (relative.empty() || *relative.begin() == "..") return file.string();
  return relative.string();
}

}  // namespace trapdem
