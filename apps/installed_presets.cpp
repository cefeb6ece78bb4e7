#include "installed_presets.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

std::optional<fs::path> installed_preset_directory() {
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running program's file
  if (ec) return std::nullopt;
  const fs::path presets = program.parent_path().parent_path() / "share" / "trapdem" / "presets";
  if (!fs::is_directory(presets, ec)) return std::nullopt;
  return presets;
}

}  // namespace trapdem::app
