#include "experiment/element_stress.hpp"

#include <limits>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/contact/law.hpp"
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

namespace {

// The point each particle's contacts are referred to in the stress sums: its centre, or for a
// member of a clump its body's centre of mass. The average stress of bodies in equilibrium is
// sum over contacts f (x) (x_c - X), X one point per body (Christoffersen, Mehrabadi & Nemat-Nasser
// 1981): a member's own centre would add the moment sum f (x) (x_member - X) of its body's contacts.
std::vector<Vec3> reference_points(const Simulation& sim) {
  const Particles& p = sim.particles();
  const RigidBodies& bodies = sim.bodies();
  if (bodies.empty()) return p.position;
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = bodies.position[bodies.body_of_particle[i]];
  return x;
}

}  // namespace

Stress3 love_weber_stress(const Simulation& sim, const ElementBox& box) {
  const Particles& p = sim.particles();
  const std::vector<Vec3> x = reference_points(sim);
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
        add(f, x[i] - wall_proximity(walls[wl.wall[k]], p.position[i]).point);
      }
    }
    add(pair_force, x[i] - o);
  }
  const double v = box.volume(sim);
  for (auto& row : s)
    for (double& x : row) x /= v;
  return s;
}

Stress3 interior_contact_stress(const Simulation& sim, const ElementBox& box, double margin) {
  Vec3 lo, hi;
  double volume = 1.0;
  for (int a = 0; a < 3; ++a) {
    lo[a] = sim.walls()[box.wall[a][0]].origin[a] + margin;
    hi[a] = sim.walls()[box.wall[a][1]].origin[a] - margin;
    if (!(hi[a] > lo[a]))
      throw SimulationError(fmt::format("element test: an interior {} m inside the walls leaves nothing of the {:.4g} m "
                                        "wide box on axis {}: lower the margin or enlarge the specimen",
                                        margin, box.length(sim, a), "xyz"[a]));
    volume *= hi[a] - lo[a];
  }
  const Particles& p = sim.particles();
  const ContactLaw& law = sim.particle_law();
  // A tangential force that is not a spring's (Blaze-DEM's viscous force) cannot be recomputed
  // from the history: the interior stress is not measured then (NaN, as for a specimen too small).
  if (!tangential_force_is_spring(law_choices(law))) {
    Stress3 unmeasured{};
    for (auto& row : unmeasured)
      for (double& x : row) x = std::numeric_limits<double>::quiet_NaN();
    return unmeasured;
  }
  const LawParams params = law_params(law, law);
  const Domain& domain = sim.settings().domain;
  const PairList pairs = sim.pairs();
  const std::vector<Vec3> x = reference_points(sim);
  Stress3 s{};
  for (std::size_t i = 0; i + 1 < pairs.first.size(); ++i) {
    for (std::uint32_t k = pairs.first[i]; k < pairs.first[i + 1]; ++k) {
      const std::uint32_t j = pairs.partner[k];
      const Vec3 branch = domain.minimum_image(p.position[i] - p.position[j]);  // from j to i
      const double distance = norm(branch);
      const double overlap = p.radius[i] + p.radius[j] - distance;
      if (!(overlap > 0.0)) continue;
      const Vec3 n = branch / distance;
      const Vec3 point = p.position[i] - (p.radius[i] - 0.5 * overlap) * n;
      bool inside = true;
      for (int a = 0; a < 3; ++a) inside = inside && point[a] >= lo[a] && point[a] < hi[a];
      if (!inside) continue;
      const double effective_radius = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
      const NormalResponse r = NormalModels::visit(law.normal_model, [&](auto model) {
        using Model = decltype(model);
        return Model::respond(static_cast<const typename Model::Params&>(params.normal), overlap, effective_radius);
      });
      const double effective_mass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
      const double c_n = RestitutionDamping::normal_coefficient(params.damping, effective_mass, r.damping_stiffness);
      const double fn = r.elastic_force - c_n * dot(p.velocity[i] - p.velocity[j], n);
      const Vec3 f = fn * n - r.tangential_stiffness * pairs.history[k].tangential_spring;
      // From j's reference point to i's: the centres, or the bodies' for members of clumps.
      const Vec3 arm = domain.minimum_image(x[i] - x[j]);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) s[a][b] += f[a] * arm[b];
    }
  }
  for (auto& row : s)
    for (double& x : row) x /= volume;
  return s;
}

}  // namespace trapdem
