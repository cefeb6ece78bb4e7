#pragma once
// LAMMPS / LIGGGHTS text dumps (`dump ... custom ... id x y z radius`), for runs made with other
// DEM codes: one file per snapshot. Recognised: the ITEM: TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS
// and ATOMS sections; in ATOMS the columns id, x|xu|xs, y|yu|ys, z|zu|zs (scaled ones mapped with
// the box bounds) and radius|diameter, in any order, other columns ignored.
#include <filesystem>
#include <string>

#include "io/snapshot.hpp"

namespace trapdem {

// Parses dump text; `source` names the file in messages. Returns a Snapshot with id, position
// and radius (step = the TIMESTEP, other fields zero). Throws InputError "<source>:<line>: ..."
// on a missing section or column, a short or non-numeric line, a wrong atom count, a repeated id
// or a second timestep in the same file.
Snapshot parse_dump(const std::string& text, const std::string& source);

// Reads and parses a file; FileError if it cannot be read.
Snapshot read_dump_file(const std::filesystem::path& path);

}  // namespace trapdem
