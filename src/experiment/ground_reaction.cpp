#include "experiment/ground_reaction.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {
constexpr const char* kHeader =
    "time_s,trapdoor_displacement_m,trapdoor_force_N,trapdoor_stress_Pa,geostatic_stress_Pa,trapdoor_stress_ratio,"
    "base_left_force_N,base_left_stress_Pa,base_left_stress_ratio,base_right_force_N,base_right_stress_Pa,"
    "base_right_stress_ratio";
}

std::string ground_reaction_csv(const std::vector<GroundReactionRow>& rows) {
  std::string out = std::string(kHeader) + "\n";
  for (const GroundReactionRow& r : rows) {
    out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n",
                       r.time, r.trapdoor_displacement, r.trapdoor.force, r.trapdoor.stress, r.geostatic_stress,
                       r.trapdoor.ratio, r.base_left.force, r.base_left.stress, r.base_left.ratio, r.base_right.force,
                       r.base_right.stress, r.base_right.ratio);
  }
  return out;
}

std::vector<GroundReactionRow> parse_ground_reaction_csv(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  std::vector<GroundReactionRow> rows;
  if (!std::getline(in, line) || line != kHeader)
    throw InputError(fmt::format("{}:1: expected the trapdoor.csv header '{}'", source, kHeader));
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    std::vector<double> v;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      try {
        v.push_back(std::stod(cell));
      } catch (const std::exception&) {
        throw InputError(fmt::format("{}:{}: '{}' is not a number", source, number, cell));
      }
      // stod reads "nan" and "inf": trapdem never writes them (a damaged or hand-edited file).
      if (!std::isfinite(v.back()))
        throw InputError(fmt::format("{}:{}: column {} is '{}': expected a finite number", source, number, v.size(), cell));
    }
    if (v.size() != 12) throw InputError(fmt::format("{}:{}: expected 12 columns, found {}", source, number, v.size()));
    GroundReactionRow r;
    r.time = v[0];
    r.trapdoor_displacement = v[1];
    r.trapdoor = {v[2], v[3], v[5]};
    r.geostatic_stress = v[4];
    r.base_left = {v[6], v[7], v[8]};
    r.base_right = {v[9], v[10], v[11]};
    rows.push_back(r);
  }
  return rows;
}

}  // namespace trapdem
