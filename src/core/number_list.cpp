#include "core/number_list.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

std::vector<double> parse_number_list(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<double> v;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ',')) {
    double x = 0.0;
    try {
      std::size_t used = 0;
      x = std::stod(item, &used);
      if (item.find_first_not_of(" \t", used) != std::string::npos) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(fmt::format("{} '{}': '{}' is not a number", what, text, item));
    }
    if (!std::isfinite(x)) throw InputError(fmt::format("{} '{}': '{}' is not a finite number", what, text, item));
    v.push_back(x);
  }
  if (v.size() != count) throw InputError(fmt::format("{} '{}': expected {} numbers separated by commas", what, text, count));
  return v;
}

}  // namespace trapdem
