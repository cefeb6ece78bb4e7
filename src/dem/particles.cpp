#include "dem/particles.hpp"

#include <numbers>

#include "dem/permutation.hpp"

namespace trapdem {

std::size_t Particles::add(std::int64_t particle_id, const Vec3& x, double r, double density, const Vec3& v,
                           const Vec3& w) {
  const double m = density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  id.push_back(particle_id);
  radius.push_back(r);
  mass.push_back(m);
  inv_mass.push_back(1.0 / m);
  inv_inertia.push_back(1.0 / (0.4 * m * r * r));
  position.push_back(x);
  velocity.push_back(v);
  angular_velocity.push_back(w);
  force.push_back({});
  torque.push_back({});
  image.push_back({});
  return id.size() - 1;
}

void Particles::reserve(std::size_t n) {
  id.reserve(n); radius.reserve(n); mass.reserve(n); inv_mass.reserve(n); inv_inertia.reserve(n);
  position.reserve(n); velocity.reserve(n); angular_velocity.reserve(n); force.reserve(n); torque.reserve(n);
  image.reserve(n);
}

void Particles::clear() {
  id.clear(); radius.clear(); mass.clear(); inv_mass.clear(); inv_inertia.clear();
  position.clear(); velocity.clear(); angular_velocity.clear(); force.clear(); torque.clear(); image.clear();
}

void Particles::truncate(std::size_t n) {
  id.resize(n); radius.resize(n); mass.resize(n); inv_mass.resize(n); inv_inertia.resize(n);
  position.resize(n); velocity.resize(n); angular_velocity.resize(n); force.resize(n); torque.resize(n);
  image.resize(n);
}


void Particles::permute(const std::vector<std::uint32_t>& p) {
  apply_permutation(id, p); apply_permutation(radius, p); apply_permutation(mass, p);
  apply_permutation(inv_mass, p); apply_permutation(inv_inertia, p); apply_permutation(position, p);
  apply_permutation(velocity, p); apply_permutation(angular_velocity, p); apply_permutation(force, p);
  apply_permutation(torque, p); apply_permutation(image, p);
}

double Particles::density(std::size_t i) const {
  const double r = radius[i];
  return mass[i] / (4.0 / 3.0 * std::numbers::pi * r * r * r);
}

double Particles::total_mass() const {
  double m = 0.0;
  for (double mi : mass) m += mi;
  return m;
}

}  // namespace trapdem
