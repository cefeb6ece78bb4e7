#include "analysis/incremental_strain.hpp"

#include <string>

#include "analysis/total_strain.hpp"
#include "core/errors.hpp"

namespace trapdem {

std::vector<PlaneStrain> incremental_strains(const TriangleMesh& mesh, const std::vector<Point2>& previous,
                                             const std::vector<Point2>& current) {
  if (previous.size() != current.size()) {
    throw InputError("incremental_strains: configurations have " + std::to_string(previous.size()) + " and " +
                     std::to_string(current.size()) + " nodes; they must be the same nodes in the same order");
  }
  std::vector<Point2> step(previous.size());
  for (std::size_t k = 0; k < previous.size(); ++k) step[k] = current[k] - previous[k];
  // Updated Lagrangian: the gradient is taken over the element's shape at the increment's start.
  return triangle_strains(mesh, previous, step);
}

AccumulatedStrain start_accumulation(std::size_t triangle_count) {
  AccumulatedStrain sum;
  sum.strain.assign(triangle_count, PlaneStrain{});
  sum.max_shear.assign(triangle_count, 0.0);
  return sum;
}

void accumulate_increment(AccumulatedStrain& sum, const std::vector<PlaneStrain>& increment) {
  if (increment.size() != sum.strain.size()) {
    throw InputError("accumulate_increment: increment has " + std::to_string(increment.size()) +
                     " triangles, accumulator " + std::to_string(sum.strain.size()));
  }
  // White & Bolton (2004): strain paths as the running sum of incremental strains per element.
  for (std::size_t t = 0; t < increment.size(); ++t) {
    sum.strain[t].exx += increment[t].exx;
    sum.strain[t].ezz += increment[t].ezz;
    sum.strain[t].gamma_xz += increment[t].gamma_xz;
    sum.max_shear[t] += maximum_shear_strain(increment[t]);
  }
  ++sum.increments;
}

AccumulatedStrain accumulated_incremental_strain(const TriangleMesh& mesh,
                                                 const std::vector<std::vector<Point2>>& configurations) {
  AccumulatedStrain sum = start_accumulation(mesh.size());
  for (std::size_t k = 1; k < configurations.size(); ++k) {
    accumulate_increment(sum, incremental_strains(mesh, configurations[k - 1], configurations[k]));
  }
  return sum;
}

}  // namespace trapdem
