#include "experiment/element_box.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {
Vec3 unit(int axis) {
  Vec3 e;
  e[axis] = 1.0;
  return e;
}
}  // namespace

double ElementBox::length(const Simulation& sim, int axis) const {
  return sim.walls()[wall[axis][1]].origin[axis] - sim.walls()[wall[axis][0]].origin[axis];
}

double ElementBox::volume(const Simulation& sim) const { return length(sim, 0) * length(sim, 1) * length(sim, 2); }

double ElementBox::face_area(const Simulation& sim, int axis) const {
  return length(sim, (axis + 1) % 3) * length(sim, (axis + 2) % 3);
}

Vec3 ElementBox::centre(const Simulation& sim) const {
  Vec3 c;
  for (int a = 0; a < 3; ++a) c[a] = 0.5 * (sim.walls()[wall[a][0]].origin[a] + sim.walls()[wall[a][1]].origin[a]);
  return c;
}

ContactLaw frictionless(const ContactLaw& with_friction) {
  ContactLaw law = with_friction;
  law.static_friction = 0.0;
  law.kinetic_friction = 0.0;
  law.rolling_friction = 0.0;
  law.rolling_model = RollingModel::none;
  return law;
}

ElementBox add_box_walls(Simulation& sim, const Vec3& lower, const Vec3& upper, const ContactLaw& wall_law) {
  ElementBox box;
  static const char* names[3][2] = {{"x_low", "x_high"}, {"y_low", "y_high"}, {"z_low", "z_high"}};
  for (int a = 0; a < 3; ++a) {
    Vec3 lo_point = lower, hi_point = upper;
    box.wall[a][0] = sim.add_wall(Wall::plane(names[a][0], lo_point, unit(a), wall_law));
    box.wall[a][1] = sim.add_wall(Wall::plane(names[a][1], hi_point, -unit(a), wall_law));
  }
  return box;
}

Grains random_gas(const SizeDistribution& sizes, double density, const ParticleShape& shape, std::int64_t count,
                  double solid_fraction, std::uint64_t seed, double& side) {
  const double bounding = shape.bounding_ratio();  // 1 for spheres
  std::mt19937_64 rng(seed);
  std::vector<double> diameter(static_cast<std::size_t>(count));
  double vs = 0.0;
  for (double& d : diameter) {
    d = sizes.sample(rng);
    const double reach = bounding * d;
    vs += std::numbers::pi / 6.0 * reach * reach * reach;
  }
  std::sort(diameter.begin(), diameter.end(), std::greater<>());
  side = std::cbrt(vs / solid_fraction);
  const double dmax = bounding * diameter.front();
  // Cells of the largest diameter: an overlap can only be with a sphere of the 27 cells around.
  const int nc = std::max(1, static_cast<int>(side / dmax));
  const double cell = side / nc;
  std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(nc) * nc * nc);
  auto cell_of = [&](double x) { return std::clamp(static_cast<int>(x / cell), 0, nc - 1); };
  std::vector<Vec3> centre;
  centre.reserve(diameter.size());
  std::uniform_real_distribution<double> unit01(0.0, 1.0);
  Grains grains;
  Particles& p = grains.particles;
  p.reserve(diameter.size());
  std::int64_t next_member_id = 1;
  for (std::size_t k = 0; k < diameter.size(); ++k) {
    const double r = 0.5 * bounding * diameter[k];  // the bounding sphere's
    bool placed = false;
    for (int attempt = 0; attempt < 100000 && !placed; ++attempt) {
      const Vec3 x{r + (side - 2 * r) * unit01(rng), r + (side - 2 * r) * unit01(rng), r + (side - 2 * r) * unit01(rng)};
      const int cx = cell_of(x.x), cy = cell_of(x.y), cz = cell_of(x.z);
      bool free = true;
      for (int i = std::max(0, cx - 1); i <= std::min(nc - 1, cx + 1) && free; ++i)
        for (int j = std::max(0, cy - 1); j <= std::min(nc - 1, cy + 1) && free; ++j)
          for (int l = std::max(0, cz - 1); l <= std::min(nc - 1, cz + 1) && free; ++l)
            for (std::uint32_t o : grid[(static_cast<std::size_t>(i) * nc + j) * nc + l]) {
              const double reach = r + 0.5 * bounding * diameter[o];
              if (norm2(centre[o] - x) < reach * reach) {
                free = false;
                break;
              }
            }
      if (!free) continue;
      grid[(static_cast<std::size_t>(cx) * nc + cy) * nc + cz].push_back(static_cast<std::uint32_t>(k));
      centre.push_back(x);
      if (shape.is_clump()) {
        const double u1 = unit01(rng), u2 = unit01(rng), u3 = unit01(rng);
        const ClumpTemplate grain = shape.clump->scaled_to(diameter[k]);
        add_rigid_body(grains.bodies, p, static_cast<std::int64_t>(k) + 1, next_member_id, grain, density, x,
                       uniform_orientation(u1, u2, u3));
        next_member_id += static_cast<std::int64_t>(grain.members.size());
      } else {
        p.add(static_cast<std::int64_t>(k) + 1, x, r, density);
      }
      placed = true;
    }
    if (!placed)
      throw SimulationError(fmt::format("element specimen: no room for particle {} of {} in the gas at a solid "
                                        "fraction of {}: lower element.gas_solid_fraction",
                                        k + 1, count, solid_fraction));
  }
  return grains;
}

double solid_volume(const Simulation& sim) {
  const RigidBodies& bodies = sim.bodies();
  if (!bodies.empty()) return std::accumulate(bodies.volume.begin(), bodies.volume.end(), 0.0);
  double v = 0.0;
  for (double r : sim.particles().radius) v += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return v;
}

}  // namespace trapdem
