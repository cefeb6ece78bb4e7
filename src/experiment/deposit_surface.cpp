#include "experiment/deposit_surface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

DepositSurface measure_deposit_surface(const Simulation& sim, const ExperimentConfig& config, Decomposition* ranks) {
  const double width = config.box.width;
  const double column = 2.0 * config.material.sizes.mean_diameter();
  const int columns = std::max(1, int(std::floor(width / column)));
  std::vector<double> tops(std::size_t(columns) + 1, -1.0);  // the last: the highest top anywhere
  double above = 0.0;
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < sim.owned_count(); ++i) {
    const double top = p.position[i].z + p.radius[i];
    const int c = std::clamp(int(std::floor(p.position[i].x / width * columns)), 0, columns - 1);
    tops[std::size_t(c)] = std::max(tops[std::size_t(c)], top);
    tops.back() = std::max(tops.back(), top);
    if (top > config.box.height) above += 1.0;
  }
  if (ranks) {
    ranks->max(tops.data(), int(tops.size()));
    above = ranks->sum(above);
  }
  DepositSurface d;
  double sum = 0.0;
  int filled = 0;
  for (int c = 0; c < columns; ++c)
    if (tops[std::size_t(c)] >= 0.0) {
      sum += tops[std::size_t(c)];
      ++filled;
    }
  d.surface = filled > 0 ? sum / filled : 0.0;
  d.highest_top = std::max(0.0, tops.back());
  d.above_box = std::size_t(std::llround(above));
  return d;
}

std::string deposit_surface_text(const DepositSurface& d, const ExperimentConfig& config) {
  std::string text = fmt::format("deposit surface at {:.1f} mm (the mean of its columns' highest tops), highest top "
                                 "{:.1f} mm",
                                 d.surface * 1e3, d.highest_top * 1e3);
  if (d.above_box > 0)
    text += fmt::format("; {} particle{} above the box's height ({:.1f} mm): a run started from this deposit needs "
                        "box.height >= {:.1f} mm",
                        d.above_box, d.above_box == 1 ? " stands" : "s stand", config.box.height * 1e3,
                        std::ceil(d.highest_top * 1e4) / 10.0);
  return text;
}

}  // namespace trapdem
