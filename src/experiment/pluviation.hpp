#pragma once
// Pluviation: particles rain into the box from a hopper band at a set flow rate, as the centrifuge
// models were prepared (the seed paper's section 2.1: consistent drop height, slow uniform flow).
//
// The free fall is not simulated: the band rides just above the deposit and particles leave it
// with the velocity of the fall, sqrt(2 g h) for the drop height h. The deposit sees the same
// impact velocity, and no step is spent on particles in flight.
#include <cstdint>
#include <map>
#include <string>

#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

class Hopper {
 public:
  explicit Hopper(const ExperimentConfig& config);

  // Inserts the particles due by the simulation's current time. Returns how many it inserted. On
  // a rank of a decomposition (`ranks`, the simulation's; collective) every rank draws the same
  // sizes and sites and inserts those whose site it owns: the pour is the one-process pour.
  std::size_t pour(Simulation& sim, Decomposition* ranks = nullptr);
  // The count reached, the surface at the fill height, or the box full (box_full()).
  bool finished(const Simulation& sim) const;
  // The deposit reached the band's ceiling (band_ceiling()) and the band found almost no free site
  // for kStalledInsertionsWhenFull insertions in a row with particles still due.
  bool box_full() const { return box_full_; }
  double band_ceiling() const;  // m: the band rides at most this high, three diameters above the rim

  std::int64_t inserted() const { return inserted_; }
  double inserted_mass() const { return inserted_mass_; }      // kg
  double surface_height() const;                               // m, estimated from the mass poured
  double entry_speed() const { return entry_speed_; }          // m/s
  bool flow_limited_by_band() const { return band_limited_; }  // the flow rate asked for was more than fits
  // s of simulated time the pour of `count` particles should take: a layer of sites per insertion
  // interval, or the flow rate's mass per second if that is slower (the progress estimate's prior).
  double planned_duration(std::int64_t count) const;

  // State for checkpoints, as key=value pairs.
  std::map<std::string, std::string> state() const;
  void restore(const std::map<std::string, std::string>& state);

 private:
  int sites_along(int axis) const;  // insertion sites across the box along x (0) or y (1)

  const ExperimentConfig* config_;
  double entry_speed_ = 0.0;      // m/s
  double spacing_ = 0.0;          // m, between insertion sites
  double interval_ = 0.0;         // s, between insertions: a layer clears the band
  double next_time_ = 0.0;        // s
  double mass_budget_ = 0.0;      // kg allowed by the flow rate and not yet poured
  std::int64_t event_ = 0;
  std::int64_t inserted_ = 0;     // grains: particles, or clumps (each a body of member spheres)
  std::int64_t next_member_id_ = 1;  // the particle id of the next clump's first member sphere
  double inserted_mass_ = 0.0;
  bool band_limited_ = false;
  // A stalled insertion: at the ceiling, fewer than 1 / kStarvedSiteFraction of the sites free while
  // particles are due. A pour at its flow rate takes about a fifth of the sites (1.5 kg/s of 2 mm
  // beads); one that stalls ten times in a row (about 10 layers' fall time) is full.
  static constexpr std::size_t kStarvedSiteFraction = 10;
  static constexpr std::int64_t kStalledInsertionsWhenFull = 10;
  std::int64_t stalled_insertions_ = 0;
  bool box_full_ = false;
};

}  // namespace trapdem
