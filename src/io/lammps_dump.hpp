#pragma once
// LAMMPS / LIGGGHTS text dumps (`dump ... custom ... id x y z radius`), for runs made with other
// DEM codes: one file per snapshot. Recognised: the ITEM: TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS
// and ATOMS sections; in ATOMS the columns id, x|xu|xs, y|yu|ys, z|zu|zs (scaled ones mapped with
// the box bounds) and radius|diameter, in any order; optional vx vy vz (velocity) and omegax
// omegay omegaz (angular velocity), each read when all three are there, and density; other
// columns ignored.
#include <filesystem>
#include <string>
#include <vector>

#include "io/snapshot.hpp"

namespace trapdem {

// A dump as read, with what a packing check needs beyond the snapshot.
struct DumpAtoms {
  Snapshot snapshot;
  std::vector<std::size_t> line;  // per atom, the 1-based line of its entry (for messages)
  std::vector<double> density;    // kg/m^3 per atom if the dump has a density column, else empty
};

// Parses dump text; `source` names the file in messages. Returns id, position, radius and, where
// the columns are there, velocity and angular velocity (else zero); step = the TIMESTEP. Throws
// InputError "<source>:<line>: ..." on a missing section or column, a short or non-numeric line,
// a wrong atom count, a repeated id, a density that is not positive, or a second timestep in the
// same file.
DumpAtoms parse_dump_atoms(const std::string& text, const std::string& source);
Snapshot parse_dump(const std::string& text, const std::string& source);  // parse_dump_atoms(...).snapshot

// Reads and parses a file; FileError if it cannot be read.
DumpAtoms read_dump_atoms(const std::filesystem::path& path);
Snapshot read_dump_file(const std::filesystem::path& path);

}  // namespace trapdem
