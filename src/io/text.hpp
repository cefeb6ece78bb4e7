#pragma once
// Small text helpers shared by the readers and writers of the io and analysis modules.
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// The words of a line, separated by spaces, tabs (and a stray carriage return).
std::vector<std::string_view> split_words(std::string_view line);

// `text` in double quotes with the escapes JSON and TOML basic strings share (\" \\ \n \t \r \b
// \f, other control characters as \u00XX).
std::string quoted(std::string_view text);

}  // namespace trapdem
