#include "dem/rigid/clump_shapes.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

std::vector<ClumpMember> dimer_members(double aspect) {
  if (!(aspect >= 1.0 && aspect < 2.0))
    throw InputError(fmt::format("dimer aspect {}: expected a number in [1, 2) (length over width)", aspect));
  // Length 2 r + d with r = 1: d = 2 (aspect - 1).
  const double half = aspect - 1.0;
  return {{{-half, 0.0, 0.0}, 1.0}, {{half, 0.0, 0.0}, 1.0}};
}

std::vector<ClumpMember> tetrahedral_members(double spacing) {
  if (!(spacing > 0.0 && spacing < 2.0))
    throw InputError(fmt::format("tetrahedral spacing {}: expected a number in (0, 2) radii", spacing));
  // Vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) are 2 sqrt(2) apart.
  const double s = spacing / (2.0 * std::numbers::sqrt2);
  return {{{s, s, s}, 1.0}, {{s, -s, -s}, 1.0}, {{-s, s, -s}, 1.0}, {{-s, -s, s}, 1.0}};
}

std::vector<ClumpMember> sub_angular_members(int satellites, double satellite_radius, double elongation,
                                             double flatness) {
  if (satellites < 2 || satellites > 20)
    throw InputError(fmt::format("sub-angular grain: {} satellites; expected 2 to 20", satellites));
  if (!(satellite_radius > 0.0 && satellite_radius <= 1.0))
    throw InputError(fmt::format("sub-angular grain: satellite radius {}; expected a number in (0, 1]", satellite_radius));
  for (const double f : {elongation, flatness})
    if (!(f >= 0.5 && f <= 2.0))
      throw InputError(fmt::format("sub-angular grain: elongation and flatness {}; expected numbers in [0.5, 2]", f));
  std::vector<ClumpMember> members{{{0.0, 0.0, 0.0}, 1.0}};
  // Fibonacci lattice on the unit sphere (Gonzalez 2010, Math. Geosci. 42, 49): evenly spread
  // directions, no two alike.
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < satellites; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / satellites;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Vec3 direction{r * std::cos(golden * k), r * std::sin(golden * k), z};
    // On the core's surface, then stretched: a satellite at most 2 core radii out, overlapping the core.
    const Vec3 centre{direction.x * elongation, direction.y, direction.z * flatness};
    const double out = norm(centre);
    members.push_back({centre * (std::min(out, 1.0 + 0.9 * satellite_radius) / out), satellite_radius});
  }
  return members;
}

std::vector<ClumpMember> read_clump_members(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the clump template", file.string()));
  std::vector<ClumpMember> members;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string word;
    std::vector<double> values;
    while (words >> word) {
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(v))
        throw InputError(fmt::format("{}:{}: '{}' is not a finite number; expected \"x y z radius\"", file.string(),
                                     number, word));
      values.push_back(v);
    }
    if (values.empty()) continue;
    if (values.size() != 4)
      throw InputError(fmt::format("{}:{}: {} numbers; expected four, \"x y z radius\"", file.string(), number,
                                   values.size()));
    if (!(values[3] > 0.0))
      throw InputError(fmt::format("{}:{}: radius {}; expected a positive number", file.string(), number, values[3]));
    members.push_back({{values[0], values[1], values[2]}, values[3]});
  }
  if (members.empty()) throw InputError(fmt::format("{}: no sphere in the clump template (lines \"x y z radius\")", file.string()));
  return members;
}

}  // namespace trapdem
