#include "experiment/presets.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/config.hpp"

namespace fs = std::filesystem;

namespace trapdem {

fs::path preset_file(const fs::path& directory, const std::string& name) {
  const fs::path path = directory / (name + ".toml");
  if (!fs::exists(path)) {
    std::string known;
    if (fs::is_directory(directory))
      for (const auto& e : fs::directory_iterator(directory))
        if (e.path().extension() == ".toml") known += (known.empty() ? "" : ", ") + e.path().stem().string();
    throw InputError(fmt::format("no preset named '{}' in {} (presets: {})", name, directory.string(), known));
  }
  return path;
}

std::vector<PresetEntry> list_presets(const fs::path& directory) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(directory))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<PresetEntry> out;
  for (const fs::path& f : files) {
    Config c = Config::load_file(f.string());
    out.push_back({f.stem().string(), c.get_string("description", "")});
  }
  return out;
}

}  // namespace trapdem
