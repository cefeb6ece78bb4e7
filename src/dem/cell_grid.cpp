#include "dem/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trapdem {

CellGrid CellGrid::covering(const std::vector<Vec3>& positions, const Domain& domain, double min_cell_size,
                            std::size_t max_cells) {
  CellGrid g;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  for (const Vec3& x : positions) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
  }
  if (positions.empty()) lo = hi = Vec3{};
  double size = min_cell_size;
  for (;;) {
    std::size_t total = 1;
    for (int a = 0; a < 3; ++a) {
      g.periodic[a] = domain.periodic[a];
      if (domain.periodic[a]) {
        const double len = domain.length(a);
        g.origin[a] = domain.lower[a];
        g.count[a] = std::max(1, static_cast<int>(std::floor(len / size)));
        g.cell_size[a] = len / g.count[a];
      } else {
        g.origin[a] = lo[a];
        g.count[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / size)) + 1);
        g.cell_size[a] = size;
      }
      total *= std::size_t(g.count[a]);
    }
    if (total <= max_cells) break;
    size *= std::cbrt(double(total) / double(max_cells)) * 1.01;
  }
  std::array<int, 3> axes{0, 1, 2};  // fastest to slowest
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return g.count[a] < g.count[b]; });
  std::size_t s = 1;
  for (int a : axes) {
    g.stride[a] = s;
    s *= std::size_t(g.count[a]);
  }
  return g;
}

int CellGrid::neighbours(std::uint32_t cell, std::array<std::uint32_t, 27>& out) const {
  int centre[3];
  for (int a = 0; a < 3; ++a) centre[a] = int((cell / stride[a]) % std::size_t(count[a]));
  // A periodic axis of one or two cells reaches the same cell twice: only then are repeats looked for.
  bool may_repeat = false;
  for (int a = 0; a < 3; ++a) may_repeat = may_repeat || (periodic[a] && count[a] < 3);
  int n = 0;
  for (int dz = -1; dz <= 1; ++dz) {
    int z = centre[2] + dz;
    if (periodic[2]) z = (z + count[2]) % count[2];
    else if (z < 0 || z >= count[2]) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      int y = centre[1] + dy;
      if (periodic[1]) y = (y + count[1]) % count[1];
      else if (y < 0 || y >= count[1]) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        int x = centre[0] + dx;
        if (periodic[0]) x = (x + count[0]) % count[0];
        else if (x < 0 || x >= count[0]) continue;
        const auto c = static_cast<std::uint32_t>(x * stride[0] + y * stride[1] + z * stride[2]);
        if (!may_repeat || std::find(out.begin(), out.begin() + n, c) == out.begin() + n) out[n++] = c;
      }
    }
  }
  return n;
}

}  // namespace trapdem
