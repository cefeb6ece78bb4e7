#pragma once
// A synthetic run folder for the whole-run tests: resolved.toml with the geometry and a
// snapshots.h5 written with append_snapshot from a jittered lattice of 2 mm particles near the
// front window (plus a few far behind it, which the front view must leave out) moved by a known
// displacement field at each trapdoor displacement.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "io/snapshot.hpp"
#include "../analysis/synthetic_points.hpp"

namespace trapdem::test {

struct SyntheticRun {
  std::filesystem::path dir;
  std::size_t front_count = 0;
  std::size_t back_count = 0;
};

// Box 0.2 x 0.01 x 0.14 m, trapdoor B = 0.05 m centred at x = 0.1. `field(p, delta)` is the
// x-z displacement of the reference point p when the trapdoor has moved delta.
inline SyntheticRun make_synthetic_run(const std::filesystem::path& dir, const std::vector<double>& deltas,
                                       const std::function<Point2(Point2, double)>& field, double z_top = 0.12,
                                       unsigned seed = 41) {
  namespace fs = std::filesystem;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "resolved.toml") << "name = \"synthetic\"\n[box]\nwidth = 0.2\ndepth = 0.01\nheight = 0.14\n"
                                          "[trapdoor]\nwidth = 0.05\ncentre = 0.1\ntravel = 0.01\ncavity_depth = 0.02\n"
                                          "[particles]\nsize = \"single\"\ndiameter = 0.002\n";
  const double d = 0.002, depth = 0.01;
  const auto front = jittered_hex_lattice(0.001, 0.199, 0.001, z_top, d, 0.2, seed);
  std::vector<Point2> back;
  for (int k = 0; k < 12; ++k) back.push_back({0.01 + 0.015 * k, 0.02 + 0.005 * k});
  SyntheticRun run{dir, front.size(), back.size()};
  for (double delta : deltas) {
    Snapshot s;
    s.stage = "lowering";
    s.trapdoor_displacement = delta;
    std::int64_t id = 1;
    auto add = [&](Point2 p, double y) {
      const Point2 u = field(p, delta);
      s.id.push_back(id++);
      s.position.push_back({p.x + u.x, y, p.z + u.z});
      s.velocity.push_back({});
      s.angular_velocity.push_back({});
      s.radius.push_back(0.5 * d);
      s.image.push_back({});
    };
    // Written in reverse id order in every other snapshot: matching must go by id.
    for (const Point2& p : front) add(p, depth - 0.5 * d);
    for (const Point2& p : back) add(p, 0.5 * d);
    if (static_cast<int>(delta * 1e4) % 2 == 1) {
      std::reverse(s.id.begin(), s.id.end());
      std::reverse(s.position.begin(), s.position.end());
    }
    append_snapshot(dir / "snapshots.h5", s);
  }
  return run;
}

}  // namespace trapdem::test
