#pragma once
// A packing made elsewhere as a run's initial particles ([packing] in the configuration): a
// LAMMPS/LIGGGHTS data file (atom_style sphere), a LAMMPS/LIGGGHTS text dump, or a snapshot of a
// trapdem run. Read with the project's readers (io/lammps_data, io/lammps_dump, io/snapshot),
// shifted into the box and checked before the run starts; the run then skips the pour.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/particles.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

// The particles as read, in file order, with where each came from.
struct PackingParticles {
  Particles particles;               // shifted; density from the file where it has one, else [particles]
  std::vector<std::string> origin;   // per particle, for messages: "<file>:<line>" or "<file> snapshot 000003, row 17"
  // A packing of clumps: the bodies whose members `particles` are (empty for spheres).
  RigidBodies bodies;
};

// Reads the packing that `packing` names (its shift applied, images cleared; velocities and
// angular velocities kept where the file has them). `default_density` (kg/m^3) is used where the
// format has no density (a dump without a density column, a trapdem snapshot). Throws InputError
// from the reader (its file:line), or for a snapshot index out of range; FileError if unreadable.
// With a clump `shape`, the packing must be a trapdem snapshot of clumps of that shape: each body
// is rebuilt from the shape scaled to its volume-equivalent diameter, at the snapshot's centre of
// mass, orientation, velocity and angular velocity, after checking that the snapshot's members
// are where that shape puts them (else an InputError naming the body: another shape); member ids
// are numbered afresh from 1, body ids kept. A snapshot of clumps with spheres for a shape, or
// spheres with a clump shape, is refused.
PackingParticles read_packing_file(const PackingConfig& packing, double default_density,
                                   const ParticleShape& shape = {});

// Every violation of the rules a run's initial particles must keep, one line each naming the
// particle id and where it came from (at most `max_lines` lines, then how many more): radius and
// density positive, ids unique, inside the box (x in [0, box.width], y in [0, box.depth] or in
// [0, depth) on a periodic depth, z up to box.height) and above the base (z - r >= 0), where a
// particle may reach into a wall by up to `max_overlap_fraction` of its radius, and no pair
// overlapping by more than `max_overlap_fraction` of the smaller radius (the engine's overlap
// guard, numerics.max_overlap_fraction; two members of one clump overlap by design and are not
// checked). Empty: the packing is fine. The pairs are found through a cell grid (no O(N^2) loop).
std::vector<std::string> packing_violations(const PackingParticles& packing, const BoxConfig& box,
                                            double max_overlap_fraction, std::size_t max_lines = 20);

// read_packing_file, then packing_violations: an InputError listing the violations if any.
PackingParticles read_packing(const PackingConfig& packing, const BoxConfig& box, double default_density,
                              double max_overlap_fraction, const ParticleShape& shape = {});

}  // namespace trapdem
