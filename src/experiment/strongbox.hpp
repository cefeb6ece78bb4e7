#pragma once
// The strongbox as walls (the seed paper's Figure 2): side walls, front window and back plate (or a
// periodic depth), the fixed base on both sides of the trapdoor, the trapdoor, and the cavity's
// vertical faces below the base, so that particles flow over the base's edges into the cavity.
#include <vector>

#include "dem/domain.hpp"
#include "dem/wall.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

// Wall names, used for the loads in trapdoor.csv.
namespace strongbox_walls {
inline constexpr const char* trapdoor = "trapdoor";
inline constexpr const char* base_left = "base_left";
inline constexpr const char* base_right = "base_right";
}  // namespace strongbox_walls

// Coordinates: x across the width (0 .. box.width), y through the depth (0 at the back plate,
// box.depth at the front window), z up (0 at the base).
std::vector<Wall> strongbox_walls_for(const ExperimentConfig& config);

// Where particles may be: the box, the cavity below the trapdoor and room above for the hopper.
// Leaving it stops the run.
Domain strongbox_domain(const ExperimentConfig& config);

}  // namespace trapdem
