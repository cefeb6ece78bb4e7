#pragma once
// Where an installed trapdem finds its presets: `make install` (CMake's install rules) puts the
// program in PREFIX/bin and the presets in PREFIX/share/trapdem/presets, so the presets are found
// from the program's own location, whatever PREFIX was chosen at install time.
#include <filesystem>
#include <optional>

namespace trapdem::app {

// PROGRAM_DIR/../share/trapdem/presets when that folder exists (an installed program); empty for
// the program in the build tree, which uses the checkout's presets/.
std::optional<std::filesystem::path> installed_preset_directory();

}  // namespace trapdem::app
