#pragma once
// Small text helpers shared by the readers and writers of the io and analysis modules.
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// The words of a line, separated by spaces, tabs (and a stray carriage return).
std::vector<std::string_view> split_words(std::string_view line);

}  // namespace trapdem
