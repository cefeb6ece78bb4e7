#pragma once
// Incremental strain between consecutive configurations, accumulated per triangle. The same node
// triples (soil elements) are followed through the whole series, and each increment is taken over
// the element's geometry at the start of the increment (updated Lagrangian), in the manner of
// White & Bolton (2004), who followed triangular soil elements through an image series to
// obtain strain paths. Unlike the total small strain, the sum of increments is not polluted by
// large rigid rotations (each increment's rotation is small).
#include <cstddef>
#include <vector>

#include "analysis/plane_strain.hpp"
#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

// Strain of each triangle from configuration `previous` to `current` (same nodes), over the
// geometry of `previous`. Compression positive.
std::vector<PlaneStrain> incremental_strains(const TriangleMesh& mesh, const std::vector<Point2>& previous,
                                             const std::vector<Point2>& current);

struct AccumulatedStrain {
  std::vector<PlaneStrain> strain;       // sum of the incremental strain components (strain path end)
  std::vector<double> max_shear;         // sum of the incremental gamma_max (cumulative shear, >= 0)
  std::size_t increments = 0;            // how many increments were added
};

// An empty accumulator for `triangle_count` triangles (all zero).
AccumulatedStrain start_accumulation(std::size_t triangle_count);

// Adds one increment (from incremental_strains) to the running sums; lets snapshots be streamed.
// Throws InputError if the sizes differ.
void accumulate_increment(AccumulatedStrain& sum, const std::vector<PlaneStrain>& increment);

// The whole series at once: configurations[0] is the reference, each next one the same nodes later.
AccumulatedStrain accumulated_incremental_strain(const TriangleMesh& mesh,
                                                 const std::vector<std::vector<Point2>>& configurations);

}  // namespace trapdem
