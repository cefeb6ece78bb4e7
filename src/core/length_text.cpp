#include "core/length_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

double parse_length(std::string_view text, std::string_view what) {
  auto fail = [&](std::string_view why) -> double {
    throw InputError(fmt::format("{} '{}': {} (write a length such as 80mm, 10 mm, 8cm or 0.08 for metres)", what,
                                 text, why));
  };
  std::string_view s = text;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.empty()) return fail("empty");
  std::size_t end = 0;
  while (end < s.size() && (std::isdigit(static_cast<unsigned char>(s[end])) || s[end] == '.' || s[end] == '-' ||
                            s[end] == '+' || s[end] == 'e' || s[end] == 'E')) {
    // 'e' only as an exponent: followed by a digit or sign
    if ((s[end] == 'e' || s[end] == 'E') &&
        !(end + 1 < s.size() && (std::isdigit(static_cast<unsigned char>(s[end + 1])) || s[end + 1] == '-' ||
                                 s[end + 1] == '+'))) {
      break;
    }
    ++end;
  }
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + end, value);
  if (ec != std::errc() || ptr != s.data() + end || end == 0) return fail("not a number");
  std::string_view unit = s.substr(end);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front()))) unit.remove_prefix(1);
  double scale = 1.0;
  if (unit.empty() || unit == "m") scale = 1.0;
  else if (unit == "mm") scale = 1e-3;
  else if (unit == "cm") scale = 1e-2;
  else if (unit == "um") scale = 1e-6;
  else return fail(fmt::format("unknown unit '{}'", unit));
  if (!std::isfinite(value)) return fail("not finite");
  return value * scale;
}

std::string format_mm(double metres) {
  std::string s = fmt::format("{:.2f}", metres * 1e3);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s + " mm";
}

std::vector<double> parse_length_list(std::string_view text, std::string_view what) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    if (item.find_first_not_of(" \t") != std::string_view::npos) out.push_back(parse_length(item, what));
    start = end + 1;
  }
  return out;
}

}  // namespace trapdem
