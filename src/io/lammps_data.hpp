#pragma once
// LAMMPS data files of atom_style sphere: the packings the peer codes (LAMMPS, LIGGGHTS) read
// and write, so that trapdem runs start from exactly the same particles.
//
// Accepted layout (LAMMPS manual, read_data):
//   first line: title (ignored)
//   header:     "N atoms", "N atom types", "xlo xhi", "ylo yhi", "zlo zhi" (others ignored)
//   "Atoms" or "Atoms # sphere": id type diameter density x y z [ix iy iz]
//   "Velocities" (optional):      id vx vy vz wx wy wz
// '#' starts a comment anywhere; blank lines are ignored; other sections are skipped.
// Units are whatever the file holds (trapdem reads SI: m, kg/m^3, m/s, rad/s).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "dem/particles.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct LammpsData {
  std::string title;           // the first line
  Particles particles;         // radius = diameter / 2, mass from density; in file order
  std::vector<int> type;       // per particle, the LAMMPS atom type
  std::vector<std::size_t> line;  // per particle, the 1-based line of its Atoms entry (for messages)
  Vec3 box_lower, box_upper;   // m: xlo ylo zlo, xhi yhi zhi
  bool has_velocities = false; // a Velocities section was read (else velocities are zero)
};

// Reads a data file; throws InputError("<path>:<line>: ... expected ...") on bad input
// (missing Atoms section or box bounds, wrong column count, non-number, count mismatch,
// duplicate or unknown id, non-positive diameter or density, other atom styles).
LammpsData read_lammps_data(const std::string& path);
// The same from a stream; `name` is used in the error messages in place of the path.
LammpsData parse_lammps_data(std::istream& in, const std::string& name);

struct LammpsWriteOptions {
  std::string title = "trapdem LAMMPS data file (atom_style sphere)";
  bool velocities = true;        // write a Velocities section
  std::vector<int> type;         // per particle; empty: all type 1
};

// Writes Atoms # sphere (with image flags) and, optionally, Velocities, in full precision so that
// reading the file back gives the same doubles. Throws InputError if the file cannot be written.
void write_lammps_data(const std::string& path, const Particles& particles, const Vec3& box_lower,
                       const Vec3& box_upper, const LammpsWriteOptions& options = {});
void write_lammps_data(std::ostream& out, const Particles& particles, const Vec3& box_lower,
                       const Vec3& box_upper, const LammpsWriteOptions& options = {});

}  // namespace trapdem
