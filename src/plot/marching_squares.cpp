#include "plot/marching_squares.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace trapdem::plot {

double ContourLine::length() const {
  double s = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) s += std::hypot(points[k].x - points[k - 1].x, points[k].z - points[k - 1].z);
  return s;
}

namespace {

enum Edge { bottom = 0, right = 1, top = 2, left = 3 };

struct Segment {
  std::uint64_t edge[2];
  Point2 point[2];
};

}  // namespace

std::vector<ContourLine> contour_lines(const GridField& field, double level) {
  const GridSpec& g = field.grid;
  std::vector<ContourLine> lines;
  if (g.nx < 2 || g.nz < 2) return lines;
  const std::uint64_t nx = g.nx;
  // Edge identifiers: horizontal edge from node (i, j) to (i + 1, j) is 2 (j nx + i), vertical
  // edge from (i, j) to (i, j + 1) is 2 (j nx + i) + 1; two cells sharing an edge share its id.
  auto edge_id = [&](std::size_t i, std::size_t j, int e) -> std::uint64_t {
    switch (e) {
      case bottom: return 2 * (j * nx + i);
      case right: return 2 * (j * nx + i + 1) + 1;
      case top: return 2 * ((j + 1) * nx + i);
      default: return 2 * (j * nx + i) + 1;
    }
  };
  std::vector<Segment> segments;
  for (std::size_t j = 0; j + 1 < g.nz; ++j) {
    for (std::size_t i = 0; i + 1 < g.nx; ++i) {
      const std::array<double, 4> v{field.at(i, j), field.at(i + 1, j), field.at(i + 1, j + 1), field.at(i, j + 1)};
      if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]) || std::isnan(v[3])) continue;
      const std::array<Point2, 4> p{Point2{g.x(i), g.z(j)}, Point2{g.x(i + 1), g.z(j)}, Point2{g.x(i + 1), g.z(j + 1)},
                                    Point2{g.x(i), g.z(j + 1)}};
      int index = 0;
      for (int k = 0; k < 4; ++k) index |= (v[k] >= level ? 1 : 0) << k;
      if (index == 0 || index == 15) continue;
      // Edge e runs from corner e to corner (e + 1) % 4.
      auto crossing = [&](int e) {
        const int a = e, b = (e + 1) % 4;
        const double t = (level - v[a]) / (v[b] - v[a]);
        return Point2{p[a].x + t * (p[b].x - p[a].x), p[a].z + t * (p[b].z - p[a].z)};
      };
      auto add = [&](int e1, int e2) {
        segments.push_back({{edge_id(i, j, e1), edge_id(i, j, e2)}, {crossing(e1), crossing(e2)}});
      };
      // The two edges meeting at corner k: (k - 1) % 4 and k.
      auto around = [&](int k) { add((k + 3) % 4, k); };
      const double centre = 0.25 * (v[0] + v[1] + v[2] + v[3]);
      switch (index) {
        case 1: case 14: around(0); break;
        case 2: case 13: around(1); break;
        case 4: case 11: around(2); break;
        case 8: case 7: around(3); break;
        case 3: case 12: add(left, right); break;
        case 6: case 9: add(bottom, top); break;
        case 5:  // corners 0 and 2 above
          if (centre >= level) { around(1); around(3); } else { around(0); around(2); }
          break;
        case 10:  // corners 1 and 3 above
          if (centre >= level) { around(0); around(2); } else { around(1); around(3); }
          break;
        default: break;
      }
    }
  }
  // Chain segments through shared edges.
  std::unordered_multimap<std::uint64_t, std::size_t> at_edge;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    at_edge.emplace(segments[s].edge[0], s);
    at_edge.emplace(segments[s].edge[1], s);
  }
  std::vector<bool> used(segments.size(), false);
  auto next_segment = [&](std::uint64_t edge, std::size_t from) -> std::ptrdiff_t {
    auto range = at_edge.equal_range(edge);
    for (auto it = range.first; it != range.second; ++it) {
      if (it->second != from && !used[it->second]) return static_cast<std::ptrdiff_t>(it->second);
    }
    return -1;
  };
  for (std::size_t s0 = 0; s0 < segments.size(); ++s0) {
    if (used[s0]) continue;
    used[s0] = true;
    std::vector<Point2> forward{segments[s0].point[0], segments[s0].point[1]};
    std::vector<Point2> backward;
    // Extend from end 1 forward, then from end 0 backward.
    for (int direction = 0; direction < 2; ++direction) {
      std::uint64_t edge = segments[s0].edge[direction == 0 ? 1 : 0];
      std::size_t from = s0;
      while (true) {
        const std::ptrdiff_t n = next_segment(edge, from);
        if (n < 0) break;
        const Segment& seg = segments[static_cast<std::size_t>(n)];
        used[static_cast<std::size_t>(n)] = true;
        const int enter = seg.edge[0] == edge ? 0 : 1;
        (direction == 0 ? forward : backward).push_back(seg.point[1 - enter]);
        edge = seg.edge[1 - enter];
        from = static_cast<std::size_t>(n);
      }
    }
    ContourLine line;
    line.points.assign(backward.rbegin(), backward.rend());
    line.points.insert(line.points.end(), forward.begin(), forward.end());
    const Point2 a = line.points.front(), b = line.points.back();
    line.closed = line.points.size() > 3 && std::hypot(a.x - b.x, a.z - b.z) <= 1e-9 * g.spacing;
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace trapdem::plot
