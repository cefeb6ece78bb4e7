#pragma once
// Initial particle arrangements: a jittered lattice to drop into a box.
#include <cstdint>

#include "dem/particles.hpp"

namespace trapdem {

struct LatticeSpec {
  Vec3 lower, upper;            // m, the region the centres fill (kept r_max away from its faces)
  double radius_min = 0.001;    // m, radii uniform in [radius_min, radius_max]
  double radius_max = 0.001;    // m
  double density = 2500.0;      // kg/m^3
  double spacing_factor = 1.05; // lattice spacing / largest diameter
  double jitter_fraction = 0.02;// random offset of each centre, fraction of the largest diameter
  std::size_t max_count = 0;    // 0: fill the region
  std::uint64_t seed = 1;
  std::int64_t first_id = 1;
};

// Simple-cubic lattice, filled layer by layer from the bottom (lowest z first). Deterministic for
// a given seed.
Particles jittered_lattice(const LatticeSpec& spec);

}  // namespace trapdem
