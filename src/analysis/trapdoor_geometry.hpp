#pragma once
// Where the trapdoor is in the plane-strain view, for the metrics that refer to it.

namespace trapdem {

struct TrapdoorGeometry {
  double centre_x = 0.0;  // m, x of the trapdoor's mid-point
  double width = 0.0;     // m, B; the edges are at centre_x -/+ width / 2
  double base_z = 0.0;    // m, height of the trapdoor (and box floor) before it moves

  double left_edge() const { return centre_x - 0.5 * width; }
  double right_edge() const { return centre_x + 0.5 * width; }
};

}  // namespace trapdem
