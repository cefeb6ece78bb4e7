#pragma once
// A piece of text without the blanks around it: option values, a command's output line.
#include <string>
#include <string_view>

namespace trapdem {

// `text` without leading and trailing characters of `blanks` (spaces, tabs and line ends by default).
inline std::string trimmed(std::string_view text, std::string_view blanks = " \t\r\n") {
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return "";
  return std::string(text.substr(first, text.find_last_not_of(blanks) - first + 1));
}

}  // namespace trapdem
