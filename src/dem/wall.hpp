#pragma once
// Walls: infinite planes and finite rectangles, fixed or moving with a prescribed velocity.
#include <algorithm>
#include <cmath>
#include <cstddef>
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
  Vec3 point;       // m, the closest point of the wall
  bool on_face;     // the closest point is inside the face (not on an edge or corner)
};

inline WallProximity wall_proximity(const Wall& w, const Vec3& x) {
  const Vec3 d = x - w.origin;
  if (w.shape == WallShape::plane) {
    const double h = dot(d, w.normal);
    return {w.normal, h, x - h * w.normal, true};
  }
  const double du = dot(d, w.axis_u), dv = dot(d, w.axis_v);
  const double su = std::clamp(du, -w.half_u, w.half_u);
  const double sv = std::clamp(dv, -w.half_v, w.half_v);
  const bool on_face = su == du && sv == dv;
  const Vec3 point = w.origin + su * w.axis_u + sv * w.axis_v;
  const Vec3 r = x - point;
  const double dist = norm(r);
  if (dist > 0.0) return {r / dist, dist, point, on_face};
  return {w.normal, 0.0, point, on_face};
}

// Whether `point` lies on the wall's surface (within `tolerance`, m).
inline bool wall_contains(const Wall& w, const Vec3& point, double tolerance) {
  const Vec3 d = point - w.origin;
  if (std::fabs(dot(d, w.normal)) > tolerance) return false;
  if (w.shape == WallShape::plane) return true;
  return std::fabs(dot(d, w.axis_u)) <= w.half_u + tolerance && std::fabs(dot(d, w.axis_v)) <= w.half_v + tolerance;
}

// Walls built of several primitives share edges (a trapdoor flush with the base, a cavity wall
// meeting it). A particle touching such a surface near the seam would otherwise feel the seam as
// a second contact. A contact therefore does not count when its closest point is that of a
// contact counted before it (both rectangles' boundary at the seam), nor, for an edge or corner
// contact, when its point lies on a face the particle touches (an edge hidden in a flat surface).
// `touching[k]` marks the candidates in contact; returns whether candidate `a` is hidden.
template <class WallOf>
bool edge_contact_hidden(std::size_t a, const WallProximity* near, const bool* touching, std::size_t count,
                         WallOf&& wall_of, double tolerance) {
  for (std::size_t b = 0; b < count; ++b) {
    if (b == a || !touching[b]) continue;
    if (b < a && norm2(near[b].point - near[a].point) <= tolerance * tolerance) return true;
    if (!near[a].on_face && near[b].on_face && wall_contains(wall_of(b), near[a].point, tolerance)) return true;
  }
  return false;
}

}  // namespace trapdem
