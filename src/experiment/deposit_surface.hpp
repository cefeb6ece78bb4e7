#pragma once
// Where a settled deposit's surface is, measured on its particles (issue 41): the pour's "surface
// at about" is the poured mass at the nominal packing fraction, which a loose deposit in a narrow
// box overshoots (the tiny preset's stood 10 mm higher, some particles above its box), and a run
// that starts from a deposit standing above its box is refused. Said when settling ends.
#include <cstddef>
#include <string>

namespace trapdem {

class Decomposition;
class Simulation;
struct ExperimentConfig;

struct DepositSurface {
  double surface = 0.0;      // m, mean over columns two mean diameters wide of the highest particle top
  double highest_top = 0.0;  // m, the highest z + r
  std::size_t above_box = 0;  // particles with z + r above box.height
};

// The own particles of `sim` (on ranks, reduced over every rank: each rank calls it).
DepositSurface measure_deposit_surface(const Simulation& sim, const ExperimentConfig& config, Decomposition* ranks);

// For run.log: "deposit surface at 42.1 mm (the mean of its columns' highest tops), highest top
// 52.8 mm", and when particles stand above the box, what that means for a run started from it.
std::string deposit_surface_text(const DepositSurface& d, const ExperimentConfig& config);

}  // namespace trapdem
