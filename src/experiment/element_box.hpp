#pragma once
// The element test's box: six frictionless infinite planes, two per axis, facing inwards. The
// particles start as a random granular gas inside it. Its lengths, volume and face areas are
// read from the walls' current positions.
#include <array>
#include <cstddef>
#include <cstdint>

#include "dem/contact_law.hpp"
#include "dem/particles.hpp"
#include "dem/simulation.hpp"
#include "experiment/size_distribution.hpp"

namespace trapdem {

struct ElementBox {
  // wall[a][0] is the lower wall of axis a (normal +e_a), wall[a][1] the upper one (normal -e_a).
  std::array<std::array<std::size_t, 2>, 3> wall{};

  double length(const Simulation& sim, int axis) const;  // m, between the two planes
  double volume(const Simulation& sim) const;            // m^3
  double face_area(const Simulation& sim, int axis) const;  // m^2, of a wall normal to `axis`
  Vec3 centre(const Simulation& sim) const;
};

// A law with the same stiffness and restitution but no friction and no rolling resistance: the
// box walls' (frictionless, as the issue asks: their shear would add to the stress ratio) and the
// dense specimen's during its compression.
ContactLaw frictionless(const ContactLaw& law);

// Adds the six planes bounding [lower, upper] to the simulation.
ElementBox add_box_walls(Simulation& sim, const Vec3& lower, const Vec3& upper, const ContactLaw& wall_law);

// `count` spheres with diameters drawn from `sizes` placed at random without overlap (random
// sequential addition, largest first) in a cube sized for `solid_fraction` (well below the
// ~0.38 at which random sequential addition jams). Returns the particles; `side` receives the
// cube's side (m), the cube being [0, side]^3.
Particles random_gas(const SizeDistribution& sizes, double density, std::int64_t count, double solid_fraction,
                     std::uint64_t seed, double& side);

double solid_volume(const Particles& p);  // m^3

}  // namespace trapdem
