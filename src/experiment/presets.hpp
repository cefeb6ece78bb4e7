#pragma once
// The presets: named configuration files (NAME.toml) in a folder; the command knows which folder
// (the source tree's presets/, or TRAPDEM_PRESETS), the library is given it.
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem {

// DIRECTORY/NAME.toml. Throws InputError naming the folder and listing its presets if there is none.
std::filesystem::path preset_file(const std::filesystem::path& directory, const std::string& name);

struct PresetEntry {
  std::string name;         // the file's stem
  std::string description;  // its `description` key
};

// Every preset of the folder, by name.
std::vector<PresetEntry> list_presets(const std::filesystem::path& directory);

}  // namespace trapdem
