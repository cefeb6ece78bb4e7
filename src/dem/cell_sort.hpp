#pragma once
// The spatial sort: the cell of every particle and the permutation that groups them cell by cell
// (the pair list's search, and the engine's re-ordering of particles in space).
#include <cstdint>
#include <vector>

#include "dem/cell_grid.hpp"
#include "dem/domain.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct CellSort {
  CellGrid grid;
  std::vector<std::uint32_t> cell_of;        // per particle
  std::vector<std::uint32_t> cell_start;     // CSR over cells into `order`
  std::vector<std::uint32_t> order;          // particle indices, cell by cell
};
CellSort sort_into_cells(const std::vector<Vec3>& positions, const Domain& domain, double cell_size);

// The sort of the particles once they are re-ordered by `sorted.order` (Particles::permute): the
// same grid and cells, each particle's cell in its new place, the identity order. What
// sort_into_cells would return for the permuted positions, without sorting again.
CellSort in_cell_order(CellSort sorted);

}  // namespace trapdem
