#pragma once
// The DEM engine: particles, walls and the step loop of the seed paper's section 4.1
// (neighbours, contacts, walls, integrate), threaded with OpenMP.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/domain.hpp"
#include "dem/engine_state.hpp"
#include "dem/force_backend.hpp"
#include "dem/history_archive.hpp"
#include "dem/integrator.hpp"
#include "dem/pair_histories.hpp"
#include "dem/pair_list.hpp"
#include "dem/particles.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "dem/rigid/body_motion.hpp"
#include "dem/rotating_frame.hpp"
#include "dem/wall.hpp"
#include "dem/wall_list.hpp"

namespace trapdem {

struct SimulationSettings {
  double time_step = 0.0;              // s; 0: time_step_fraction of the critical step
  double time_step_fraction = 0.2;     // of critical_time_step() when time_step is 0
  double skin = 0.0;                   // m, Verlet skin; 0: 0.2 x the mean diameter
  Domain domain;                       // leaving it on a bounded axis stops the run
  double max_overlap_fraction = 0.25;  // overlap / smaller radius above which the run stops
  bool freeze_rotation = false;        // spheres do not rotate (a block that slides, a test device)
  int reorder_every = 1;               // re-order particles in space every this many rebuilds (0: never)
};

// Counters of what the engine did (for logs and benchmarks).
struct SimulationStats {
  std::int64_t rebuilds = 0;
  std::int64_t steps = 0;
  double rebuild_seconds = 0.0;  // s of wall-clock time in rebuilds, in this process (not checkpointed)
  // On a rank of a decomposition (this process; not checkpointed): the ghosts held, summed over
  // the steps (mean halo = ghost_steps / steps), and the wall-clock seconds spent in the ghost
  // exchanges (positions out, forces back) and the reductions of the step.
  std::int64_t ghost_steps = 0;
  double exchange_seconds = 0.0;
};

class Decomposition;    // the parallel back end (decomposition.hpp)

class Simulation {
 public:
  // With `bodies` (clumps, rigid/rigid_bodies.hpp) the particles are their members, every one of
  // them (add_rigid_body builds both). A run with bodies needs one process and no periodic axis.
  Simulation(Particles particles, const ContactLaw& particle_law, SimulationSettings settings,
             RigidBodies bodies = {});
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  ~Simulation();

  // Gravity (m/s^2) as a function of time; constant by default.
  void set_gravity(const Vec3& g);
  void set_gravity(std::function<Vec3(double)> g);
  Vec3 gravity() const;  // at the current time

  // A frame turning about a fixed axis (rotating_frame.hpp): centrifugal, Euler and Coriolis
  // forces on each particle at its own position, on top of the uniform gravity. None by default:
  // then the step is the uniform-gravity step, unchanged. The frame is not checkpointed: its owner
  // sets it again on a resume, as it does the gravity.
  void set_rotating_frame(RotatingFrame frame);
  void clear_rotating_frame();
  const RotatingFrame* rotating_frame() const { return frame_.get(); }

  // A wall's contact law is fixed when it is added (the engine keeps it in the form its loops
  // read); its motion is changed through the calls below, never by reference.
  std::size_t add_wall(Wall wall);
  const Wall& wall(std::size_t k) const { return state_.walls.at(k); }
  const std::vector<Wall>& walls() const { return state_.walls; }
  std::size_t find_wall(const std::string& name) const;  // throws if absent
  // Prescribed velocity (m/s) as a function of time (s); an empty function fixes the wall.
  void set_wall_velocity(std::size_t k, std::function<Vec3(double)> velocity);
  void set_wall_velocity(std::size_t k, const Vec3& velocity);  // constant
  // A checkpoint's wall state: position, travel since the start, last load and velocity.
  void restore_wall_state(std::size_t k, const Vec3& origin, const Vec3& displacement, const Vec3& force,
                          const Vec3& torque, const Vec3& current_velocity);

  // Adds particles during a run (pluviation); the lists are rebuilt before the next step. On a
  // decomposition each rank adds the particles whose sites it owns (owns_site).
  bool owns_site(const Vec3& x) const;
  void add_particle(std::int64_t id, const Vec3& x, double radius, double density, const Vec3& v = {});
  void remove_particles(const std::vector<std::uint32_t>& indices);  // not in a run with bodies
  // Adds a rigid body during a run (a clump's pluviation; add_rigid_body, rigid_bodies.hpp): in a
  // run of bodies only (one without particles, or whose particles are all members of bodies).
  void add_body(std::int64_t body_id, std::int64_t first_member_id, const ClumpTemplate& shape, double density,
                const Vec3& position, const Quaternion& orientation, const Vec3& velocity = {},
                const Vec3& angular_velocity = {});
  const RigidBodies& bodies() const { return state_.bodies; }

  void step();
  void run(std::int64_t steps);

  // The force back end (force_backend.hpp): the threaded CPU one unless another is set before the
  // first step; the engine hands it the particle law and every wall's law.
  void set_force_backend(std::unique_ptr<ForceBackend> backend);
  const ForceBackend& force_backend() const { return *backend_; }

  // Runs this Simulation as one rank of a domain decomposition (decomposition.hpp; the MPI one is
  // src/parallel): every rank builds the same Simulation (same particles, walls, settings), then
  // attaches its rank's decomposition before the first step and keeps its share of the particles.
  // From then on step() and the diagnostics below are collective (every rank calls them).
  void set_decomposition(std::unique_ptr<Decomposition> decomposition);
  const Decomposition* decomposition() const { return decomposition_.get(); }

  // particles() holds the owned particles first ([0, owned_count())), then, on a rank of a
  // decomposition, the ghosts (copies of other ranks' particles). Without one: all are owned.
  const Particles& particles() const { return state_.particles; }
  std::size_t owned_count() const { return state_.owned(); }
  Particles& particles_mutable() { invalidate_lists(); return state_.particles; }
  const ContactLaw& particle_law() const { return law_; }
  const SimulationSettings& settings() const { return settings_; }
  PairList pairs() const;  // a copy, with each listed pair's contact history
  const WallList& wall_candidates() const { return state_.lists.walls; }
  const SimulationStats& stats() const { return stats_; }
  double time() const { return time_; }
  std::int64_t step_count() const { return stats_.steps; }
  double time_step() const { return dt_; }

  // m, the Verlet skin of the next list build. A change (a stage of an experiment with a skin of
  // its own) does not rebuild the lists: they stay valid for the skin they were built with
  // (lists_outdated compares with it), and the next rebuild, when they are outdated, uses the new one.
  void set_skin(double skin);
  double skin() const { return skin_; }

  // s, the smallest contact time scale over the particles and the laws (the particle law's and
  // the walls'), as the normal model defines it (trapdem::critical_time_step, contact_law.hpp):
  // sqrt(m_min / k_max) for linear springs, the Rayleigh time for Hertz.
  double critical_time_step() const;

  // The engine's complete state beyond particles and walls, for checkpoints: with it, a resumed
  // run continues bit for bit as the uninterrupted one (same thread count).
  struct ListState {
    PairList pairs;
    WallList walls;
    std::vector<Vec3> position_at_build;
    std::vector<Vec3> wall_displacement_at_build;
    std::int64_t rebuilds_since_reorder = 0;
    double skin_at_build = 0.0;  // m; 0: not known (an earlier version's checkpoint): the current skin
  };
  ListState list_state() const;
  // Restores time, counters and lists; particles (forces and torques included), bodies
  // (restore_bodies) and walls (origin, displacement, load) must already hold the checkpoint's values. On a rank of a decomposition the
  // particles are the rank's as checkpointed (owned, then `ghosts` ghosts) and the decomposition's
  // own state is restored by its owner.
  void restore(double time, const SimulationStats& stats, ListState lists, std::size_t ghosts = 0);
  // A checkpoint's bodies (every per-body and per-member array but the derived ones), before restore().
  void restore_bodies(RigidBodies bodies);
  // Resumes from a state without lists (a checkpoint of another rank count): particles (forces and
  // torques included, all of them on every rank) and walls already set; the contact histories come
  // by ids and the next step rebuilds the lists. With a decomposition attached, each rank keeps
  // its share of the particles and of the histories.
  void resume_from_histories(double time, const SimulationStats& stats, HistoryArchive histories);

  // Diagnostics (deterministic serial sums; on a decomposition: of the owned particles, summed over
  // the ranks in rank order).
  double translational_kinetic_energy() const;  // J
  double rotational_kinetic_energy() const;     // J
  double kinetic_energy() const { return translational_kinetic_energy() + rotational_kinetic_energy(); }
  // J, -m g . x relative to the reference; in a rotating frame plus the frame's potential
  // m omega^2 (r_h^2 - r^2) / 2, r_h the radius of the point at z = reference_height on the
  // line through the axis point along z (the height above the base when z is the model's vertical).
  double potential_energy(double reference_height = 0.0) const;
  std::size_t contact_count() const;            // touching particle pairs
  double total_mass() const;                    // kg, of the particles, or of the bodies when there are
  double max_overlap_fraction() const { return max_overlap_seen_; }

 private:
  void integrate_positions();
  BodyKick body_kick(const FrameKick* frame) const;  // this step's half kick of the bodies
  std::optional<FrameKick> frame_kick_now() const;   // the rotating frame's half kick at the current time, if any
  void check_bodies_allowed(const char* what) const;  // one process, no periodic axis
  // Whether a pair or particle-wall contact could form unlisted before the next build, given the
  // displacements of every particle (on ranks, of all the ranks' particles).
  bool lists_outdated(const DisplacementsSinceBuild& all) const;
  // The step's parts that cross a sub-domain boundary (halo.cpp): each does nothing more than the
  // one-process work without a decomposition.
  enum class NextLists { keep, rebuild, stop };
  NextLists agree_on_next_lists();     // stop: a particle escaped on some rank
  void rebuild_lists_agreed();         // a failure on one rank thrown on every rank
  void update_ghosts();                // the ghosts' positions and velocities from their owners
  void forces(bool fused_kick);        // the back end's pass, then the ghosts' shares and the wall loads summed
  void check_stability_agreed();       // every rank throws the first failure, or none
  void drop_ghosts();            // their histories kept for the next rebuild
  int kick_owned();              // the second half kick of the owned particles (decomposed_step.cpp)
  SecondHalfKick second_half_kick();  // this step's, for kick_owned and a back end's fused kick
  double global_sum(double local) const;
  void rebuild_lists();
  std::int64_t first_non_finite_particle() const;
  void check_stability() const;  // diagnostics.cpp
  void invalidate_lists() { lists_valid_ = false; }
  void find_particles_near_walls();
  void find_partner_reach();
  void size_contact_arrays();
  void compact_pair_history();
  std::string describe_particle(std::uint32_t i) const;

  EngineState state_;  // the particles, walls, lists and contact histories (engine_state.hpp)
  std::unique_ptr<ForceBackend> backend_;  // the force passes over state_ (force_backend.hpp)
  ContactLaw law_;
  SimulationSettings settings_;
  std::unique_ptr<Decomposition> decomposition_;  // null: one process
  std::function<Vec3(double)> gravity_;
  Vec3 constant_gravity_;
  bool gravity_is_constant_ = true;
  std::unique_ptr<RotatingFrame> frame_;  // null: uniform gravity only

  HistoryArchive pending_history_;  // archived before particles were removed
  HistoryArchive archive_;  // the rebuild's: its arrays reused from one rebuild to the next, not state
  bool history_pending_ = false;
  std::vector<ContactHistory> pair_history() const;  // per listed pair, from the compact form
  bool lists_valid_ = false;
  bool setup_done_ = false;
  std::int64_t rebuilds_since_reorder_ = 0;

  double dt_ = 0.0;
  double skin_ = 0.0;
  double time_ = 0.0;
  SimulationStats stats_;

  // Set by the kernels, read by check_stability().
  DisplacementsSinceBuild displacements_;  // of the owned particles, this step
  double max_overlap_seen_ = 0.0;
  std::int64_t bad_particle_ = -1;     // non-finite state
  std::int64_t escaped_particle_ = -1;
};

}  // namespace trapdem
