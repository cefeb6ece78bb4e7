#pragma once
// Reading a whole text file, with a FileError naming the file when it cannot be read.
#include <filesystem>
#include <string>

namespace trapdem {

std::string read_text_file(const std::filesystem::path& path);

}  // namespace trapdem
