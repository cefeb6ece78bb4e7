#include "parallel/gather.hpp"

#include <algorithm>
#include <cstring>

#include "parallel/particle_record.hpp"

namespace trapdem {

namespace {

std::vector<ParticleRecord> owned_records(const Simulation& sim) {
  const Particles& p = sim.particles();
  std::vector<ParticleRecord> mine;
  mine.reserve(sim.owned_count());
  for (std::size_t i = 0; i < sim.owned_count(); ++i) mine.push_back(record_of(p, i));
  return mine;
}

Particles in_id_order(std::vector<ParticleRecord> all) {
  std::sort(all.begin(), all.end(), [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
  Particles out;
  out.reserve(all.size());
  for (const ParticleRecord& r : all) append_record(out, r);
  return out;
}

}  // namespace

Particles gather_particles(const Simulation& sim, MPI_Comm comm) {
  const std::vector<ParticleRecord> mine = owned_records(sim);
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const int bytes = int(mine.size() * sizeof(ParticleRecord));
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks), 0);
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < ranks; ++r) offsets[std::size_t(r)] = offsets[std::size_t(r) - 1] + counts[std::size_t(r) - 1];
  std::vector<ParticleRecord> all(std::size_t(offsets.back() + counts.back()) / sizeof(ParticleRecord));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  return in_id_order(std::move(all));
}

// Sizes first, then the bytes (MPI counts are int: a rank's share stays below 2 GB, ~15 M
// particles' records; the total on rank 0 may exceed it and is received rank by rank).
std::vector<char> gather_bytes_on_root(const std::vector<char>& mine, MPI_Comm comm, std::vector<std::size_t>* lengths) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::uint64_t size = mine.size();
  std::vector<std::uint64_t> sizes(std::size_t(ranks), 0);
  MPI_Gather(&size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, 0, comm);
  if (rank != 0) {
    MPI_Send(mine.data(), int(size), MPI_BYTE, 0, 201, comm);
    return {};
  }
  std::vector<char> all;
  for (int r = 0; r < ranks; ++r) {
    const std::size_t at = all.size();
    all.resize(at + sizes[std::size_t(r)]);
    if (r == 0)
      std::copy(mine.begin(), mine.end(), all.begin() + std::ptrdiff_t(at));
    else
      MPI_Recv(all.data() + at, int(sizes[std::size_t(r)]), MPI_BYTE, r, 201, comm, MPI_STATUS_IGNORE);
    if (lengths) lengths->push_back(sizes[std::size_t(r)]);
  }
  return all;
}

Particles gather_particles_on_root(const Simulation& sim, MPI_Comm comm) {
  const std::vector<ParticleRecord> mine = owned_records(sim);
  const char* begin = reinterpret_cast<const char*>(mine.data());
  const std::vector<char> bytes = gather_bytes_on_root(std::vector<char>(begin, begin + mine.size() * sizeof(ParticleRecord)), comm);
  std::vector<ParticleRecord> all(bytes.size() / sizeof(ParticleRecord));
  if (!all.empty()) std::memcpy(all.data(), bytes.data(), bytes.size());
  return in_id_order(std::move(all));
}

}  // namespace trapdem
