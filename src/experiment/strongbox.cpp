#include "experiment/strongbox.hpp"

#include <algorithm>

namespace trapdem {

std::vector<Wall> strongbox_walls_for(const ExperimentConfig& c) {
  const double w = c.box.width, d = c.box.depth;
  const double b = c.trapdoor.width, xc = c.trapdoor.centre, cavity = c.trapdoor.cavity_depth;
  const double left_edge = xc - 0.5 * b, right_edge = xc + 0.5 * b;
  // With a periodic depth the base rectangles reach past the period by the interaction range, so
  // that a particle that has crossed y = 0 or y = depth between list builds still finds the face.
  const double reach = c.box.periodic_depth ? 2.0 * c.material.sizes.max_diameter() + c.largest_skin() : 0.0;
  const double half_depth = 0.5 * d + reach;
  const Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  const ContactLaw& base = c.material.base;

  std::vector<Wall> walls;
  walls.push_back(Wall::plane("left", {0, 0, 0}, ex, base));
  walls.push_back(Wall::plane("right", {w, 0, 0}, -ex, base));
  if (!c.box.periodic_depth) {
    walls.push_back(Wall::plane("back", {0, 0, 0}, ey, c.material.back));
    walls.push_back(Wall::plane("front", {0, d, 0}, -ey, c.material.front));
  }
  walls.push_back(Wall::rectangle(strongbox_walls::base_left, {0.5 * left_edge, 0.5 * d, 0}, ex, 0.5 * left_edge,
                                  ey, half_depth, base));
  walls.push_back(Wall::rectangle(strongbox_walls::base_right, {0.5 * (right_edge + w), 0.5 * d, 0}, ex,
                                  0.5 * (w - right_edge), ey, half_depth, base));
  walls.push_back(Wall::rectangle(strongbox_walls::trapdoor, {xc, 0.5 * d, 0}, ex, 0.5 * b, ey, half_depth, base));
  walls.push_back(Wall::rectangle("cavity_left", {left_edge, 0.5 * d, -0.5 * cavity}, ez, 0.5 * cavity, ey,
                                  half_depth, base));
  walls.push_back(Wall::rectangle("cavity_right", {right_edge, 0.5 * d, -0.5 * cavity}, ez, 0.5 * cavity, ey,
                                  half_depth, base));
  return walls;
}

Domain strongbox_domain(const ExperimentConfig& c) {
  Domain dom;
  const double margin = 2.0 * c.material.sizes.max_diameter();
  dom.lower = {-margin, -margin, -c.trapdoor.cavity_depth - margin};
  // Above the box: room for the hopper band, which stays just above the surface (see pluviation.hpp).
  dom.upper = {c.box.width + margin, c.box.depth + margin, c.box.height + 6.0 * c.material.sizes.max_diameter() + margin};
  if (c.box.periodic_depth) {
    dom.lower.y = 0.0;
    dom.upper.y = c.box.depth;
    dom.periodic[1] = true;
  }
  return dom;
}

}  // namespace trapdem
