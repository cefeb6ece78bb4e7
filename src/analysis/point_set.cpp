#include "analysis/point_set.hpp"

#include <string>

#include "core/errors.hpp"

namespace trapdem {

PointSet2 point_set_between(const std::vector<Point2>& reference, const std::vector<Point2>& current) {
  if (reference.size() != current.size()) {
    throw InputError("point_set_between: reference has " + std::to_string(reference.size()) +
                     " nodes but current has " + std::to_string(current.size()) +
                     "; match particles by id before building the point set");
  }
  PointSet2 points;
  points.position = reference;
  points.displacement.resize(reference.size());
  for (std::size_t k = 0; k < reference.size(); ++k) points.displacement[k] = current[k] - reference[k];
  return points;
}

std::vector<Point2> current_positions(const PointSet2& points) {
  std::vector<Point2> current(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) current[k] = points.position[k] + points.displacement[k];
  return current;
}

std::vector<double> vertical_displacements(const PointSet2& points) {
  std::vector<double> w(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) w[k] = points.displacement[k].z;
  return w;
}

}  // namespace trapdem
