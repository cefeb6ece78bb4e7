#include "dem/cell_sort.hpp"

#include <numeric>

namespace trapdem {

CellSort sort_into_cells(const std::vector<Vec3>& positions, const Domain& domain, double cell_size) {
  CellSort s;
  const std::size_t n = positions.size();
  s.grid = CellGrid::covering(positions, domain, cell_size, 4 * n + 64);
  s.cell_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.cell_of[i] = s.grid.index(positions[i]);
  // Counting sort: stable, so the order within a cell follows the current index order.
  s.cell_start.assign(s.grid.total() + 1, 0);
  for (std::uint32_t c : s.cell_of) ++s.cell_start[c + 1];
  std::partial_sum(s.cell_start.begin(), s.cell_start.end(), s.cell_start.begin());
  s.order.resize(n);
  std::vector<std::uint32_t> fill(s.cell_start.begin(), s.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) s.order[fill[s.cell_of[i]]++] = static_cast<std::uint32_t>(i);
  return s;
}

CellSort in_cell_order(CellSort sorted) {
  std::vector<std::uint32_t> cell_of(sorted.order.size());
  for (std::size_t k = 0; k < sorted.order.size(); ++k) cell_of[k] = sorted.cell_of[sorted.order[k]];
  sorted.cell_of = std::move(cell_of);
  std::iota(sorted.order.begin(), sorted.order.end(), 0u);
  return sorted;
}

}  // namespace trapdem
