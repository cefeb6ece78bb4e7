#pragma once
#include "dem/vec3.hpp"

namespace trapdem {

// The region particles may occupy. A particle outside it on a bounded axis has escaped (the run
// stops); on a periodic axis it re-enters on the other side.
struct Domain {
  Vec3 lower;                          // m
  Vec3 upper;                          // m
  bool periodic[3] = {false, false, false};

  double length(int axis) const { return upper[axis] - lower[axis]; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }

  // The minimum-image separation on periodic axes.
  Vec3 minimum_image(Vec3 d) const {
    for (int a = 0; a < 3; ++a) {
      if (periodic[a]) {
        const double len = length(a);
        if (d[a] > 0.5 * len) d[a] -= len;
        else if (d[a] < -0.5 * len) d[a] += len;
      }
    }
    return d;
  }
};

}  // namespace trapdem
