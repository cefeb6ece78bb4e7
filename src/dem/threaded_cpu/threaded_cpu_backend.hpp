#pragma once
// The threaded CPU force back end (force_backend.hpp): one contact-major sweep over each thread's
// block of particles (threaded_cpu_backend.cpp), the pair and wall batch loops the compiler
// vectorises (pair_sweep.cpp, wall_sweep.cpp), and the second half kick fused into the sweep.
#include <string_view>
#include <vector>

#include "dem/contact/law.hpp"
#include "dem/force_backend.hpp"
#include "dem/threaded_cpu/pair_sweep.hpp"
#include "dem/threaded_cpu/wall_sweep.hpp"

namespace trapdem {

class ThreadedCpuBackend final : public ForceBackend {
 public:
  std::string_view name() const override { return "threaded CPU"; }
  bool fuses_second_half_kick() const override { return true; }
  void set_particle_law(const LawParams& params, const LawChoices& choices) override;
  void add_wall_law(const LawParams& params, const LawChoices& choices) override;
  ForcePassResult compute_forces(EngineState& state, const ForcePass& pass) override;

 private:
  void add_deferred_shares(Particles& p) const;
  int kick_after_deferred_shares(const EngineState& state, const SecondHalfKick& kick, int threads) const;
  void sum_wall_loads(std::vector<Wall>& walls, int threads) const;

  // The laws as the batch loops read them.
  LawParams particle_params_{};
  LawChoices particle_choices_{};
  WallLaws wall_laws_;  // per wall

  // Per thread (the workspaces; nothing here outlives a pass's meaning).
  std::vector<std::vector<PartnerShare>> deferred_;  // shares for later threads' particles
  std::vector<ContactBatch> batches_;
  std::vector<WallBatch> wall_batches_;
  std::vector<Vec3> wall_loads_;  // per thread and wall: force, torque
};

}  // namespace trapdem
