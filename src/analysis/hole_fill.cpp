#include "analysis/hole_fill.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Each pending element takes the mean of its neighbours that have a finite value, layer by layer
// from the valued ones inward: a layer's elements read only values set before that layer, so the
// result does not depend on the order. for_each_neighbour(k, f) calls f(m) for each neighbour m
// of k. Returns how many got a value; an element whose region holds no value stays NaN.
template <class ForEachNeighbour>
std::size_t fill_layer_by_layer(std::vector<double>& value, std::vector<std::size_t> pending,
                                ForEachNeighbour&& for_each_neighbour) {
  std::size_t filled = 0;
  while (!pending.empty()) {
    std::vector<std::pair<std::size_t, double>> layer;
    std::vector<std::size_t> still;
    for (const std::size_t k : pending) {
      double sum = 0.0;
      int count = 0;
      for_each_neighbour(k, [&](std::size_t m) {
        if (std::isfinite(value[m])) {
          sum += value[m];
          ++count;
        }
      });
      if (count > 0)
        layer.emplace_back(k, sum / count);
      else
        still.push_back(k);
    }
    if (layer.empty()) break;  // only elements without any valued neighbour left: they stay empty
    for (const auto& [k, v] : layer) value[k] = v;
    filled += layer.size();
    pending = std::move(still);
  }
  return filled;
}

// The triangles on each side of every edge, kept ones numbered 0..K-1 and dropped ones K..K+D-1.
struct EdgeNeighbours {
  // across[t][e]: the triangle across edge e of triangle t (kNone on the outer boundary).
  std::vector<std::array<std::size_t, 3>> across;
};

EdgeNeighbours edge_neighbours(const std::vector<const TriangleNodes*>& all) {
  std::unordered_map<std::uint64_t, std::pair<std::size_t, int>> first_side;  // edge -> (triangle, edge slot)
  first_side.reserve(all.size() * 2);
  EdgeNeighbours n;
  n.across.assign(all.size(), {kNone, kNone, kNone});
  for (std::size_t t = 0; t < all.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      std::uint64_t a = (*all[t])[static_cast<std::size_t>(e)], b = (*all[t])[static_cast<std::size_t>((e + 1) % 3)];
      if (a > b) std::swap(a, b);
      const std::uint64_t key = (a << 32) ^ b;  // node indices below 2^32 (a view of millions of particles)
      const auto [it, inserted] = first_side.emplace(key, std::make_pair(t, e));
      if (!inserted) {
        n.across[t][static_cast<std::size_t>(e)] = it->second.first;
        n.across[it->second.first][static_cast<std::size_t>(it->second.second)] = t;
      }
    }
  }
  return n;
}

}  // namespace

FilledHoles fill_interior_holes(const FilteredMesh& mesh, const std::vector<double>& kept_values) {
  const std::size_t kept = mesh.mesh.size(), dropped = mesh.dropped.size();
  if (kept_values.size() != kept)
    throw InputError(fmt::format("fill_interior_holes: {} values for {} kept triangles", kept_values.size(), kept));
  std::vector<const TriangleNodes*> all;
  all.reserve(kept + dropped);
  for (const auto& t : mesh.mesh.triangles) all.push_back(&t);
  for (const auto& t : mesh.dropped.triangles) all.push_back(&t);
  const EdgeNeighbours n = edge_neighbours(all);

  // Outside: dropped triangles on the outer boundary, and the dropped ones reached from them.
  std::vector<char> outside(kept + dropped, 0);
  std::vector<std::size_t> stack;
  for (std::size_t t = kept; t < kept + dropped; ++t)
    for (const std::size_t other : n.across[t])
      if (other == kNone && !outside[t]) {
        outside[t] = 1;
        stack.push_back(t);
      }
  while (!stack.empty()) {
    const std::size_t t = stack.back();
    stack.pop_back();
    for (const std::size_t other : n.across[t])
      if (other != kNone && other >= kept && !outside[other]) {
        outside[other] = 1;
        stack.push_back(other);
      }
  }

  // Values, layer by layer inward from the kept triangles.
  std::vector<double> value(kept + dropped, std::nan(""));
  for (std::size_t t = 0; t < kept; ++t) value[t] = kept_values[t];
  std::vector<std::size_t> pending;
  for (std::size_t t = kept; t < kept + dropped; ++t)
    if (!outside[t]) pending.push_back(t);
  fill_layer_by_layer(value, std::move(pending), [&](std::size_t t, auto&& each) {
    for (const std::size_t other : n.across[t])
      if (other != kNone) each(other);
  });

  FilledHoles filled;
  for (std::size_t t = kept; t < kept + dropped; ++t) {
    if (!outside[t] && std::isfinite(value[t])) {
      filled.triangles.triangles.push_back(*all[t]);
      filled.values.push_back(value[t]);
    } else {
      ++filled.left_empty;
    }
  }
  return filled;
}

GridField fill_interior_grid_holes(const GridField& field, double wall_left, double wall_right, std::size_t* filled) {
  const std::size_t nx = field.grid.nx, nz = field.grid.nz;
  if (field.value.size() != nx * nz)
    throw InputError(fmt::format("fill_interior_grid_holes: {} values for a {} x {} grid", field.value.size(), nx, nz));
  GridField out = field;
  std::vector<double>& v = out.value;
  auto missing = [&](std::size_t k) { return !std::isfinite(v[k]); };
  // Strictly between the walls: a node on a wall is never covered (the particles' centres stay a
  // radius away), and a column of them would be a way out along the wall.
  const double tolerance = 1e-9 * field.grid.spacing;  // m
  auto in_box = [&](std::size_t k) {
    const double x = field.grid.x(k % nx);
    return x > wall_left + tolerance && x < wall_right - tolerance;
  };
  // The NaN nodes between the walls reachable from the top or bottom row through such nodes: empty
  // space, left as it is.
  std::vector<char> outside(v.size(), 0);
  std::vector<std::size_t> stack;
  auto visit = [&](std::size_t k) {
    if (missing(k) && !outside[k] && in_box(k)) {
      outside[k] = 1;
      stack.push_back(k);
    }
  };
  for (std::size_t i = 0; i < nx; ++i) {  // the bottom and top rows (not the side columns: walls)
    visit(i);
    visit((nz - 1) * nx + i);
  }
  auto neighbours = [&](std::size_t k, auto&& each) {
    const std::size_t i = k % nx, j = k / nx;
    if (i > 0) each(k - 1);
    if (i + 1 < nx) each(k + 1);
    if (j > 0) each(k - nx);
    if (j + 1 < nz) each(k + nx);
  };
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    stack.pop_back();
    neighbours(k, visit);
  }
  // The holes, filled layer by layer from the nodes with values inward.
  std::vector<std::size_t> hole;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (missing(k) && !outside[k] && in_box(k)) hole.push_back(k);
  const std::size_t count = fill_layer_by_layer(v, std::move(hole), neighbours);
  if (filled) *filled = count;
  return out;
}

}  // namespace trapdem
