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
  while (!pending.empty()) {
    std::vector<std::pair<std::size_t, double>> layer;
    std::vector<std::size_t> still;
    for (const std::size_t t : pending) {
      double sum = 0.0;
      int count = 0;
      for (const std::size_t other : n.across[t])
        if (other != kNone && std::isfinite(value[other])) {
          sum += value[other];
          ++count;
        }
      if (count > 0)
        layer.emplace_back(t, sum / count);
      else
        still.push_back(t);
    }
    if (layer.empty()) break;  // only triangles without any valued neighbour left: they stay empty
    for (const auto& [t, v] : layer) value[t] = v;
    pending = std::move(still);
  }

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

}  // namespace trapdem
