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
#include "dem/rigid/rigid_bodies.hpp"
#include "experiment/particle_shape.hpp"
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

// A specimen's grains: spheres (no bodies), or clumps (every particle a member of a body).
struct Grains {
  Particles particles;
  RigidBodies bodies;
};

// `count` grains of `shape` with (volume-equivalent) diameters drawn from `sizes` placed at random
// without overlap (random sequential addition of their bounding spheres, largest first; a clump
// in a uniformly random orientation) in a cube sized for the bounding spheres to fill
// `solid_fraction` of it (well below the ~0.38 at which random sequential addition jams). `side`
// receives the cube's side (m), the cube being [0, side]^3. Spheres draw as they always did.
Grains random_gas(const SizeDistribution& sizes, double density, const ParticleShape& shape, std::int64_t count,
                  double solid_fraction, std::uint64_t seed, double& side);

double solid_volume(const Simulation& sim);  // m^3: of the spheres, or of the clumps' unions

}  // namespace trapdem
