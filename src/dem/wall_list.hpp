#pragma once
// The Verlet list of particle-wall candidates: per particle, the walls within its radius plus
// the skin, with each candidate's contact history and last force.
#include <cstdint>
#include <vector>

#include "dem/contact/contact_history.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace trapdem {

// The most walls one particle may have within reach (a corner of a box has three).
inline constexpr std::uint32_t kMaxWallCandidates = 16;

// Per particle, the walls within reach: wall[k] for k in [first[i], first[i+1]).
struct WallList {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> wall;
  std::vector<ContactHistory> history;
  std::vector<Vec3> force;   // N, force on the particle from this wall in the last step

  std::size_t size() const { return wall.size(); }
};

// Builds the particle-wall candidates closer than r_i + skin, of the first n particles (a rank's
// owned ones: ghosts' wall contacts are their owners').
void build_wall_candidates(const Particles& p, std::size_t n, const std::vector<Wall>& walls, double skin,
                           WallList& out);

}  // namespace trapdem
