#include "piv/control_point_file.hpp"

#include <cctype>
#include <fstream>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/number_list.hpp"

namespace trapdem {

std::vector<ControlPoint> parse_control_points(std::istream& in, const std::string& name) {
  std::vector<ControlPoint> points;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (!(std::isdigit(static_cast<unsigned char>(line[first])) || line[first] == '-' || line[first] == '.')) continue;  // header
    if (line.back() == '\r') line.pop_back();
    const auto v = parse_number_list(line, 4, fmt::format("{}:{}", name, number));
    points.push_back({{v[0], v[1]}, {v[2], v[3]}});
  }
  return points;
}

std::vector<ControlPoint> read_control_points(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the control point file", file.string()));
  return parse_control_points(in, file.string());
}

}  // namespace trapdem
