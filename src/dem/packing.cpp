#include "dem/packing.hpp"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

Particles jittered_lattice(const LatticeSpec& s) {
  if (!(s.radius_min > 0.0) || s.radius_max < s.radius_min)
    throw InputError(fmt::format("lattice: radii must satisfy 0 < radius_min <= radius_max (got {} and {} m)",
                                 s.radius_min, s.radius_max));
  const double d = 2.0 * s.radius_max;
  const double spacing = s.spacing_factor * d;
  const double jitter = s.jitter_fraction * d;
  int count[3];
  for (int a = 0; a < 3; ++a) {
    const double len = s.upper[a] - s.lower[a] - d;
    count[a] = len >= 0.0 ? 1 + static_cast<int>(std::floor(len / spacing)) : 0;
  }
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> radius(s.radius_min, s.radius_max);
  Particles p;
  std::int64_t id = s.first_id;
  for (int k = 0; k < count[2]; ++k) {
    for (int j = 0; j < count[1]; ++j) {
      for (int i = 0; i < count[0]; ++i) {
        if (s.max_count != 0 && p.size() >= s.max_count) return p;
        const Vec3 x{s.lower.x + s.radius_max + i * spacing + jitter * unit(rng),
                     s.lower.y + s.radius_max + j * spacing + jitter * unit(rng),
                     s.lower.z + s.radius_max + k * spacing + jitter * unit(rng)};
        const double r = s.radius_min == s.radius_max ? s.radius_min : radius(rng);
        p.add(id++, x, r, s.density);
      }
    }
  }
  return p;
}

}  // namespace trapdem
