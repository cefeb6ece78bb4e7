#pragma once
// The particle core: spheres as a structure of arrays. Only what every kernel needs lives
// here; anything else (material index, colour, tracers) belongs to the module that uses it.
#include <cstdint>
#include <vector>

#include "dem/vec3.hpp"

namespace trapdem {

struct Int3 {
  std::int32_t x = 0, y = 0, z = 0;
  std::int32_t& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
};

struct Particles {
  std::vector<std::int64_t> id;          // stable identity, survives re-ordering
  std::vector<double> radius;            // m
  std::vector<double> mass;              // kg
  std::vector<double> inv_mass;          // 1/kg
  std::vector<double> inv_inertia;       // 1/(kg m^2), solid sphere I = 2/5 m r^2
  std::vector<Vec3> position;            // m
  std::vector<Vec3> velocity;            // m/s
  std::vector<Vec3> angular_velocity;    // rad/s
  std::vector<Vec3> force;               // N, contact forces of the current step (gravity not included)
  std::vector<Vec3> torque;              // N m
  std::vector<Int3> image;               // periodic images crossed, to unwrap positions

  std::size_t size() const { return id.size(); }
  bool empty() const { return id.empty(); }

  // Appends a solid sphere of the given density (kg/m^3). Returns its index.
  std::size_t add(std::int64_t particle_id, const Vec3& position, double radius, double density,
                  const Vec3& velocity = {}, const Vec3& angular_velocity = {});
  void reserve(std::size_t n);
  void clear();
  void truncate(std::size_t n);  // keeps the first n particles

  // Applies a permutation: new index k takes what old index new_to_old[k] held.
  void permute(const std::vector<std::uint32_t>& new_to_old);

  double density(std::size_t i) const;  // kg/m^3, from mass and radius
  double total_mass() const;
};

}  // namespace trapdem
