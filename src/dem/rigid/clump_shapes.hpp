#pragma once
// The clump shapes trapdem builds in, and a user's template file (issue 39). Each gives member
// spheres in a frame of its own, in any length unit: make_clump_template centres and orients them
// and a run scales them to each particle's volume-equivalent diameter from the size distribution.
#include <filesystem>
#include <vector>

#include "dem/rigid/clump_template.hpp"

namespace trapdem {

// Two equal spheres; `aspect` = length / width in [1, 2) (1: one sphere's outline, the two centres
// coinciding; 2 would be two spheres just touching, no longer one body).
std::vector<ClumpMember> dimer_members(double aspect);

// Four equal spheres on the vertices of a regular tetrahedron, the centres `spacing` radii apart
// (in (0, 2): overlapping).
std::vector<ClumpMember> tetrahedral_members(double spacing = 1.0);

// A sub-angular grain: a core sphere of radius 1 and `satellites` spheres of radius
// `satellite_radius` (relative to the core's) whose centres lie on the core's surface in the
// directions of a Fibonacci lattice on the sphere, stretched by `elongation` along x and
// `flatness` along z (both 1: equant). Deterministic: the same parameters, the same grain.
// satellites in [2, 20], satellite_radius in (0, 1], elongation and flatness in [0.5, 2].
std::vector<ClumpMember> sub_angular_members(int satellites, double satellite_radius, double elongation = 1.0,
                                             double flatness = 1.0);

// A template file: one member per line, "x y z radius" (the same length unit throughout), '#' to
// the end of a line is a comment, blank lines are skipped. Throws InputError naming the file and
// line: a line that is not four numbers, a radius that is not positive.
std::vector<ClumpMember> read_clump_members(const std::filesystem::path& file);

}  // namespace trapdem
