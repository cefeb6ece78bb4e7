#include "experiment/element_stress.hpp"

#include "dem/wall.hpp"

namespace trapdem {

double wall_normal_stress(const Simulation& sim, const ElementBox& box, int axis, int side) {
  const Wall& w = sim.walls()[box.wall[axis][side]];
  return -dot(w.force, w.normal) / box.face_area(sim, axis);
}

Vec3 wall_stress(const Simulation& sim, const ElementBox& box) {
  Vec3 s;
  for (int a = 0; a < 3; ++a) s[a] = 0.5 * (wall_normal_stress(sim, box, a, 0) + wall_normal_stress(sim, box, a, 1));
  return s;
}

Stress3 love_weber_stress(const Simulation& sim, const ElementBox& box) {
  const Particles& p = sim.particles();
  const WallList& wl = sim.wall_candidates();
  const std::vector<Wall>& walls = sim.walls();
  const Vec3 o = box.centre(sim);
  Stress3 s{};
  auto add = [&s](const Vec3& f, const Vec3& l) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[i][j] += f[i] * l[j];
  };
  const bool has_walls = wl.first.size() == p.size() + 1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 pair_force = p.force[i];
    if (has_walls) {
      for (std::uint32_t k = wl.first[i]; k < wl.first[i + 1]; ++k) {
        const Vec3& f = wl.force[k];
        if (f == Vec3{}) continue;  // a candidate not touching
        pair_force -= f;
        add(f, p.position[i] - wall_proximity(walls[wl.wall[k]], p.position[i]).point);
      }
    }
    add(pair_force, p.position[i] - o);
  }
  const double v = box.volume(sim);
  for (auto& row : s)
    for (double& x : row) x /= v;
  return s;
}

}  // namespace trapdem
