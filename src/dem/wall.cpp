#include "dem/wall.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {
Vec3 unit(const Vec3& v, const std::string& name, const char* what) {
  const double len = norm(v);
  if (!(len > 0.0) || !std::isfinite(len)) throw InputError(fmt::format("wall '{}': {} must be a non-zero vector", name, what));
  return v / len;
}
}  // namespace

Wall Wall::plane(std::string name, const Vec3& point, const Vec3& normal, const ContactLaw& law) {
  Wall w;
  w.normal = unit(normal, name, "normal");
  w.name = std::move(name);
  w.shape = WallShape::plane;
  w.origin = point;
  w.law = law;
  law.validate("wall '" + w.name + "'");
  return w;
}

Wall Wall::rectangle(std::string name, const Vec3& centre, const Vec3& u, double half_u, const Vec3& v,
                     double half_v, const ContactLaw& law) {
  Wall w;
  w.axis_u = unit(u, name, "axis u");
  w.axis_v = unit(v, name, "axis v");
  if (std::fabs(dot(w.axis_u, w.axis_v)) > 1e-9) throw InputError(fmt::format("wall '{}': axes u and v must be orthogonal", name));
  if (!(half_u > 0.0) || !(half_v > 0.0)) throw InputError(fmt::format("wall '{}': half-extents must be positive (got {}, {})", name, half_u, half_v));
  w.normal = cross(w.axis_u, w.axis_v);
  w.name = std::move(name);
  w.shape = WallShape::rectangle;
  w.origin = centre;
  w.half_u = half_u;
  w.half_v = half_v;
  w.law = law;
  law.validate("wall '" + w.name + "'");
  return w;
}

}  // namespace trapdem
