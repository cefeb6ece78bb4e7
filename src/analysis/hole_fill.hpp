#pragma once
// A triangle field drawn without holes (issue 41). The filter (triangle_filter.hpp) leaves out
// triangles that are not soil elements: those over the free surface and the hull, which are empty
// space, but also long-edge and sliver triangles inside the specimen, which would show as white
// scratches in a strain map. This finds the dropped triangles inside: those that cannot be
// reached from the mesh's outer boundary (an edge with one triangle) through dropped triangles
// alone, and gives each a value interpolated from its neighbours, layer by layer from the kept
// triangles inward (each the mean of its edge neighbours that have a value, kept or filled in an
// earlier layer). A display aid: the fields written to files and every metric use the kept
// triangles only.
#include <cstddef>
#include <vector>

#include "analysis/grid_field.hpp"
#include "analysis/triangle_filter.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

struct FilledHoles {
  TriangleMesh triangles;      // the dropped triangles inside the specimen
  std::vector<double> values;  // each one's interpolated value
  std::size_t left_empty = 0;  // dropped triangles connected to the outer boundary (empty space)
};

// `kept_values` holds a value per kept triangle of `mesh` (mesh.mesh order); non-finite values
// count as missing. Throws InputError if its size differs from the kept triangles'.
FilledHoles fill_interior_holes(const FilteredMesh& mesh, const std::vector<double>& kept_values);

// The same for a grid field in the x-z plane of a specimen (a stored field_history.h5 layer, which
// samples the kept triangles: a node that no kept triangle covered is NaN). Empty space is what
// can be reached through NaN nodes (4-neighbours) from the grid's top or bottom row: above the
// free surface, a crater open to it, below the base beside a lowered trapdoor; only through nodes
// strictly between the box's side walls (x in (wall_left, wall_right), m): on and beyond them is
// not the specimen's space, and a NaN node beside a wall (where no triangle reached it) is inside.
// Each NaN node inside gets the mean of its finite 4-neighbours, layer by layer from the finite
// nodes inward; empty space and the nodes on and beyond the walls stay NaN. A display aid.
// `filled` (optional) receives the number of nodes filled.
GridField fill_interior_grid_holes(const GridField& field, double wall_left, double wall_right,
                                   std::size_t* filled = nullptr);

}  // namespace trapdem
