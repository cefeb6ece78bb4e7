#pragma once
// Particles that left the domain across a periodic axis re-enter on the other side.
#include "dem/domain.hpp"
#include "dem/particles.hpp"

namespace trapdem {

// Wraps positions on the periodic axes into [lower, upper), counting the images crossed
// (Particles::image, to unwrap positions). Done at list rebuilds: between them a particle moves
// less than the skin (far less than half the periodic length, at least twice the interaction
// range), and the pair kernel takes the minimum image.
void wrap_periodic(Particles& p, const Domain& domain);

}  // namespace trapdem
