#pragma once
// The plane-strain view of a granular specimen: particle centres projected on the width-height
// plane (x = width, z = height, both in metres, z up) with their displacements. The analysis
// module works on this plain data only; reading snapshots and choosing which particles are seen
// (front slab or all) happens before.
#include <cstddef>
#include <vector>

namespace trapdem {

struct Point2 {
  double x = 0.0;  // m, across the box width
  double z = 0.0;  // m, height, up positive
};

constexpr Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.z + b.z}; }
constexpr Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.z - b.z}; }
constexpr Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.z}; }

// Reference centres and their displacements to the current configuration, node k in both.
struct PointSet2 {
  std::vector<Point2> position;      // m, reference configuration
  std::vector<Point2> displacement;  // m, current minus reference (u along x, w along z)

  std::size_t size() const { return position.size(); }
};

// Builds the point set from two configurations of the same nodes (same order).
// Throws InputError if the sizes differ.
PointSet2 point_set_between(const std::vector<Point2>& reference, const std::vector<Point2>& current);

// Reference position plus displacement, node by node.
std::vector<Point2> current_positions(const PointSet2& points);

// Vertical displacement w of every node (m, up positive; a settlement is negative).
std::vector<double> vertical_displacements(const PointSet2& points);

}  // namespace trapdem
