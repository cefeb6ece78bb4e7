#include "parallel/gather.hpp"

#include <algorithm>

#include "parallel/particle_record.hpp"

namespace trapdem {

Particles gather_particles(const Simulation& sim, MPI_Comm comm) {
  const Particles& p = sim.particles();
  std::vector<ParticleRecord> mine;
  mine.reserve(sim.owned_count());
  for (std::size_t i = 0; i < sim.owned_count(); ++i) mine.push_back(record_of(p, i));
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const int bytes = int(mine.size() * sizeof(ParticleRecord));
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks), 0);
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < ranks; ++r) offsets[std::size_t(r)] = offsets[std::size_t(r) - 1] + counts[std::size_t(r) - 1];
  std::vector<ParticleRecord> all(std::size_t(offsets.back() + counts.back()) / sizeof(ParticleRecord));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  std::sort(all.begin(), all.end(), [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
  Particles out;
  out.reserve(all.size());
  for (const ParticleRecord& r : all) append_record(out, r);
  return out;
}

}  // namespace trapdem
