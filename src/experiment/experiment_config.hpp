#pragma once
// The trapdoor experiment's configuration: geometry, materials, stages, numerics and output, read
// from TOML through the strict parameter dictionary (every key documented in docs/config.md).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/particles.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "dem/vec3.hpp"
#include "experiment/particle_shape.hpp"
#include "experiment/size_distribution.hpp"

namespace trapdem {

class Config;

struct BoxConfig {
  double width = 0.325;        // m (x)
  double depth = 0.0182;       // m (y), between the front window and the back plate
  double height = 0.36;        // m (z), above the base
  bool periodic_depth = false; // no front and back walls: the depth is periodic
};

struct TrapdoorConfig {
  double width = 0.05;         // m
  double centre = 0.1625;      // m, x of its centre (default: the middle of the box)
  double travel = 0.08;        // m, downward displacement at the end of the run
  double rate = 0.05;          // m/s, constant lowering velocity
  double cavity_depth = 0.09;  // m, depth of the cavity below the base (default: travel + 10 mm)
};

struct MaterialConfig {
  double density = 2500.0;     // kg/m^3 of the solid
  SizeDistribution sizes = SizeDistribution::single(0.002);  // of the volume-equivalent diameter
  ParticleShape shape;         // [particles.shape]: spheres, or rigid clumps (particle_shape.hpp)
  ContactLaw particle;         // particle-particle (Table 2)
  ContactLaw base;             // particle against the base, trapdoor, cavity and side walls
  ContactLaw front;            // particle against the front window (glass)
  ContactLaw back;             // particle against the back plate (aluminium)

  std::vector<const ContactLaw*> wall_laws() const;  // base, front, back
  // The keys a table gives that no model of its law reads (a preset's friction under Blaze-DEM's
  // law), each with the choices that would read it; said in run.log, not an error: a study may
  // switch a preset's law and cannot remove the preset's keys.
  std::vector<std::string> unread_parameters;
};

struct PluviationConfig {
  std::int64_t count = 0;      // particles to pour (0: pour until fill_height)
  double fill_height = 0.0;    // m, estimated surface height that ends the pour (0: by count)
  double drop_height = 0.2;    // m, free fall from the hopper: particles enter at sqrt(2 g h)
  double flow_rate = 0.0;      // kg/s (0: as fast as the hopper band allows)
  double packing_fraction = 0.6; // assumed solid fraction of the deposit, for the surface estimate
  std::uint64_t seed = 1;
  // The Verlet skin while pouring, fraction of the largest diameter (0: numerics.skin_fraction).
  // The rain sets how often the lists are rebuilt (beads falling onto beads bouncing up); 3x the
  // run's skin rebuilds a third as often, but every pair of the bed below pays for the longer lists:
  // faster on a 60 000-bead pour, not on a 100 000-bead one (bench/RESULTS.md, 2026-12-07).
  double skin_fraction = 0.0;
};

// [packing]: start from particles made elsewhere instead of pouring (packing_input.hpp).
struct PackingConfig {
  std::string from;              // path of the file (or run folder); empty: the run pours
  std::string format;            // "lammps-data", "lammps-dump" or "trapdem"
  std::int64_t snapshot = -1;    // "trapdem": index in the file's snapshot list; -1: the last
  Vec3 shift;                    // m, added to every position
  bool start_at_spin_up = false; // start_stage = "spin_up" (else "settling")
  // Read and checked by ExperimentConfig::from (file order, shift applied); null without [packing].
  std::shared_ptr<const Particles> particles;
  // A packing of clumps (a trapdem snapshot of clumps, [particles.shape] the same shape): the
  // bodies whose members `particles` are; null for spheres.
  std::shared_ptr<const RigidBodies> bodies;
  double critical_time_step = 0.0;  // s, the smallest over the packing's particles (grains)

  bool enabled() const { return !from.empty(); }
};

struct SettlingConfig {
  double energy_ratio = 1e-6;  // settled when translational kinetic / potential energy falls below it
  double min_time = 0.01;      // s
  double max_time = 0.5;       // s; beyond it the stage ends with a warning
};

struct SpinUpConfig {
  double g_level = 50.0;       // final gravity in multiples of 9.81 m/s^2
  double ramp_time = 0.05;     // s, linear ramp from 1 g
};

// [centrifuge]: the model in the rotating frame of a centrifuge (centrifuge_frame.hpp) from the
// spin-up on, instead of a uniform gravity. Off unless the table is there (then spin_up.g_level is
// the g level at the reference level).
struct CentrifugeConfig {
  bool enabled = false;
  double radius = 0.0;                 // m, from the axis to the reference level
  std::string reference = "effective"; // "base", "surface" or "effective" (a third of the model's height below the surface)
  bool width_in_plane = true;          // the box's width (x) in the plane of rotation; else along the axis
  bool coriolis = true;
  bool euler = true;
  double model_height = 0.0;           // m, the soil model's height above the base (derived)

  double reference_height() const;     // m, z of the reference level above the base
};

struct NumericsConfig {
  double time_step = 0.0;            // s (0: time_step_fraction of the critical step)
  double time_step_fraction = 0.2;   // of the critical step
  double skin_fraction = 0.2;        // Verlet skin, fraction of the largest diameter
  double max_overlap_fraction = 0.25;
  int threads = 0;                   // 0: all cores
};

struct OutputConfig {
  std::vector<double> snapshot_displacements{0.0, 0.005, 0.01, 0.02, 0.04, 0.08};  // m
  double ground_reaction_step = 0.0005;  // m of trapdoor travel between trapdoor.csv rows
  double checkpoint_interval = 600.0;    // s of wall-clock time
  double log_interval = 10.0;            // s of wall-clock time between progress lines
};

struct ExperimentConfig {
  std::string name = "trapdoor";
  std::string description;
  BoxConfig box;
  TrapdoorConfig trapdoor;
  MaterialConfig material;
  PluviationConfig pluviation;
  PackingConfig packing;
  SettlingConfig settling;
  SpinUpConfig spin_up;
  CentrifugeConfig centrifuge;
  NumericsConfig numerics;
  OutputConfig output;

  static constexpr double standard_gravity = 9.81;  // m/s^2, 1 g

  // Reads every section, checks ranges and consistency, reports unknown keys (file:line) and
  // adds the derived values (time step, particle count, critical step) to the resolved record.
  static ExperimentConfig from(Config& config);

  // The specimen alone: name, description, box, trapdoor, pluviation.fill_height,
  // spin_up.g_level, particles.density and [centrifuge] (its model height as the run's
  // derived.centrifuge_model_height when given), read with the same keys, defaults and rules as from(); other keys are left
  // unread and not reported, other members keep their defaults. What the analyses of a run folder
  // need from its resolved.toml (RunFolder), and what a short file describing a run made with
  // another code gives them (--config FILE with [box] and [trapdoor]).
  static ExperimentConfig specimen_from(Config& config);

  // s, trapdem::critical_time_step for the smallest particle (sqrt(m_min / k_max) for linear
  // springs, the Rayleigh time for Hertz): the one the engine computes. With a packing, the
  // smallest over its particles.
  double critical_time_step() const;
  double time_step() const;           // s
  double skin() const;                // m, the Verlet skin after the pour (and of a run from a packing)
  double pour_skin() const;           // m, the Verlet skin while pouring
  double largest_skin() const;        // m, the larger of the two: the reach of what a skin bounds
  std::int64_t expected_particle_count() const;  // with a packing: its particle count
};

}  // namespace trapdem
