#pragma once
// The force computation behind one interface: the contact forces and torques of the engine's state
// (engine_state.hpp) for one step. The threaded CPU back end (threaded_cpu/) implements it today;
// a GPU back end implements the same call on device copies of the same declared arrays, and a clump
// reduction (the member spheres' forces summed onto their rigid bodies before the kick) wraps a back
// end. The physics is not the back end's: every back end runs the contact law's sub-models
// (contact/law.hpp) for the laws it is given; a back end decides only the loops, their order and
// where the data lives. What a back end can do beyond the forces is a capability it declares (the
// fused second half kick), and the engine asks for it only where the step allows it.
#include <memory>
#include <string_view>

#include "dem/contact/law.hpp"
#include "dem/domain.hpp"
#include "dem/engine_state.hpp"
#include "dem/integrator.hpp"

namespace trapdem {

// What a force pass is given beside the state.
struct ForcePass {
  const Domain& domain;  // the minimum image on its periodic axes
  double dt;             // s, the step (the tangential springs' increments)
  // The step's second half kick, for a back end that fuses it (ForceBackend::fuses_second_half_kick):
  // each owned particle is kicked once its force is complete. Null: the forces only; the engine
  // kicks afterwards.
  const SecondHalfKick* second_half_kick = nullptr;
};

struct ForcePassResult {
  double max_overlap_fraction = 0.0;  // the largest overlap / smaller radius over the pass's contacts
  bool kicked_not_finite = false;     // a particle's velocity or spin not finite after the fused kick
};

class ForceBackend {
 public:
  virtual ~ForceBackend() = default;

  virtual std::string_view name() const = 0;

  // Capability: the second half kick inside the pass, each particle as soon as its force is
  // complete (it spares a pass over the particle state).
  virtual bool fuses_second_half_kick() const = 0;

  // The laws as the engine resolved them (contact_law.hpp: law_params, law_choices): the particles'
  // once, before any pass; each wall's when the wall is added, in the walls' order.
  virtual void set_particle_law(const LawParams& params, const LawChoices& choices) = 0;
  virtual void add_wall_law(const LawParams& params, const LawChoices& choices) = 0;

  // One force pass over the state, whose lists are valid for its positions. Reads every particle's
  // position, velocity, spin, radius, mass and inverse inertia (ghosts included), the lists and
  // last pass's histories (lists.contacts, lists.walls). Writes every particle's force and torque
  // (from zero: a ghost's are the shares its owner receives), this pass's histories (into
  // lists.contacts_next, then swapped with lists.contacts; lists.pair_contact renumbered; the wall
  // candidates' histories and forces in place) and each wall's load (force, torque) from this
  // process's particles. A pass is deterministic for a given state and thread count.
  virtual ForcePassResult compute_forces(EngineState& state, const ForcePass& pass) = 0;
};

// The threaded CPU back end (threaded_cpu/threaded_cpu_backend.hpp): OpenMP, the thread count of
// the calling scope (ThreadScope).
std::unique_ptr<ForceBackend> make_threaded_cpu_backend();

}  // namespace trapdem
