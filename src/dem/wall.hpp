#pragma once
// Walls: infinite planes and finite rectangles, fixed or moving with a prescribed velocity.
#include <algorithm>
#include <functional>
#include <string>

#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

enum class WallShape { plane, rectangle };

struct Wall {
  std::string name;
  WallShape shape = WallShape::plane;
  Vec3 origin;              // m: a point of the plane, or the rectangle's centre
  Vec3 normal{0, 0, 1};     // unit; a plane acts on the side it points to
  Vec3 axis_u, axis_v;      // rectangle: unit in-plane axes
  double half_u = 0.0;      // m, rectangle half-extent along axis_u
  double half_v = 0.0;      // m
  ContactLaw law;           // particle-wall contact parameters (own friction, rolling)
  // Prescribed velocity (m/s) as a function of time (s); empty: the wall is fixed.
  std::function<Vec3(double)> velocity;

  // Load the particles put on the wall in the last step (N, and N m about `origin`):
  // the sum over contacts of the force exerted BY the particles ON the wall. A floor carrying a
  // bed under gravity -g e_z therefore reads force.z = -(weight).
  Vec3 force;
  Vec3 torque;
  Vec3 displacement;        // m, travelled since the start
  Vec3 current_velocity;    // m/s, in the last step

  static Wall plane(std::string name, const Vec3& point, const Vec3& normal, const ContactLaw& law);
  // A rectangle centred at `centre` spanned by the (orthogonal) axes u and v with half-extents;
  // its normal is u x v (both faces are in contact).
  static Wall rectangle(std::string name, const Vec3& centre, const Vec3& u, double half_u, const Vec3& v,
                        double half_v, const ContactLaw& law);
};

// Contact geometry between a sphere and a wall: the unit normal from the wall's closest point
// towards the centre and the distance to it. Rectangles use the closest point on the face, the
// edges or the corners.
struct WallProximity {
  Vec3 normal;
  double distance;  // m, signed for planes (negative: the centre is behind the plane)
};

inline WallProximity wall_proximity(const Wall& w, const Vec3& x) {
  const Vec3 d = x - w.origin;
  if (w.shape == WallShape::plane) return {w.normal, dot(d, w.normal)};
  const double su = std::clamp(dot(d, w.axis_u), -w.half_u, w.half_u);
  const double sv = std::clamp(dot(d, w.axis_v), -w.half_v, w.half_v);
  const Vec3 r = d - su * w.axis_u - sv * w.axis_v;
  const double dist = norm(r);
  if (dist > 0.0) return {r / dist, dist};
  return {w.normal, 0.0};
}

}  // namespace trapdem
