#pragma once
// The ground reaction curve: the load on the trapdoor and on the fixed base beside it against
// the trapdoor's displacement (Iglesia, Einstein & Whitman 2014), written as trapdoor.csv.
#include <string>
#include <vector>

namespace trapdem {

struct BaseLoad {
  double force = 0.0;    // N, vertical load the particles put on the wall (downward positive)
  double stress = 0.0;   // Pa, force over the wall's area
  double ratio = 0.0;    // stress over its value before lowering
};

struct GroundReactionRow {
  double time = 0.0;                  // s
  double trapdoor_displacement = 0.0; // m, downward positive
  BaseLoad trapdoor;
  double geostatic_stress = 0.0;      // Pa, trapdoor stress before lowering (the reference of trapdoor.ratio)
  BaseLoad base_left, base_right;     // the fixed base on each side
};

// CSV text with a header naming each column and its unit.
std::string ground_reaction_csv(const std::vector<GroundReactionRow>& rows);
// Parses what ground_reaction_csv wrote (for resume and for the figures).
std::vector<GroundReactionRow> parse_ground_reaction_csv(const std::string& text, const std::string& source);

}  // namespace trapdem
