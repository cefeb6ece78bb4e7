#include "parallel/mpi_run_ranks.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "parallel/failure_agreement.hpp"
#include "parallel/gather.hpp"
#include "parallel/particle_record.hpp"

namespace trapdem {

namespace {

void put_string(Packer& packer, const std::string& text) { packer.put(std::vector<char>(text.begin(), text.end())); }
std::string get_string(Unpacker& unpacker) {
  const std::vector<char> text = unpacker.get<char>();
  return {text.begin(), text.end()};
}

void put_particles(Packer& packer, const Particles& p) {
  std::vector<ParticleRecord> records;
  records.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) records.push_back(record_of(p, i));
  packer.put(records);
}
Particles get_particles(Unpacker& unpacker) {
  Particles p;
  for (const ParticleRecord& r : unpacker.get<ParticleRecord>()) append_record(p, r);
  return p;
}

void put_lists(Packer& packer, const Simulation::ListState& lists) {
  packer.put(lists.pairs.first);
  packer.put(lists.pairs.partner);
  packer.put(lists.pairs.history);
  packer.put(lists.walls.first);
  packer.put(lists.walls.wall);
  packer.put(lists.walls.history);
  packer.put(lists.walls.force);
  packer.put(lists.position_at_build);
  packer.put(lists.wall_displacement_at_build);
  packer.put(std::vector<std::int64_t>{lists.rebuilds_since_reorder});
  packer.put(std::vector<double>{lists.skin_at_build});
}
Simulation::ListState get_lists(Unpacker& unpacker) {
  Simulation::ListState lists;
  lists.pairs.first = unpacker.get<std::uint32_t>();
  lists.pairs.partner = unpacker.get<std::uint32_t>();
  lists.pairs.history = unpacker.get<ContactHistory>();
  lists.walls.first = unpacker.get<std::uint32_t>();
  lists.walls.wall = unpacker.get<std::uint32_t>();
  lists.walls.history = unpacker.get<ContactHistory>();
  lists.walls.force = unpacker.get<Vec3>();
  lists.position_at_build = unpacker.get<Vec3>();
  lists.wall_displacement_at_build = unpacker.get<Vec3>();
  const std::vector<std::int64_t> reorder = unpacker.get<std::int64_t>();
  if (reorder.size() != 1) throw FileError("a checkpointed rank state without its re-order count");
  lists.rebuilds_since_reorder = reorder[0];
  const std::vector<double> skin = unpacker.get<double>();
  if (skin.size() != 1) throw FileError("a checkpointed rank state without its lists' skin");
  lists.skin_at_build = skin[0];
  return lists;
}

void put_rank(Packer& packer, const RankState& rank) {
  put_particles(packer, rank.particles);
  packer.put(std::vector<std::uint64_t>{rank.ghosts});
  put_lists(packer, rank.lists);
  packer.put(rank.decomposition);
}
RankState get_rank(Unpacker& unpacker) {
  RankState rank;
  rank.particles = get_particles(unpacker);
  const std::vector<std::uint64_t> ghosts = unpacker.get<std::uint64_t>();
  if (ghosts.size() != 1 || ghosts[0] > rank.particles.size()) throw FileError("a checkpointed rank state's ghost count");
  rank.ghosts = ghosts[0];
  rank.lists = get_lists(unpacker);
  rank.decomposition = unpacker.get<std::uint8_t>();
  return rank;
}

void put_histories(Packer& packer, const HistoryArchive& histories) {
  packer.put(histories.pairs);
  packer.put(histories.walls);
}
HistoryArchive get_histories(Unpacker& unpacker) {
  HistoryArchive histories;
  histories.pairs = unpacker.get<HistoryArchive::PairRecord>();
  histories.walls = unpacker.get<HistoryArchive::WallRecord>();
  return histories;
}

// What every rank needs of a checkpoint whatever the rank count: time, counters, walls, metadata.
void put_common(Packer& packer, const Checkpoint& c) {
  packer.put(std::vector<double>{c.time, c.time_step});
  packer.put(std::vector<std::int64_t>{c.stats.steps, c.stats.rebuilds});
  packer.put(std::vector<std::uint64_t>{c.walls.size(), c.metadata.size()});
  for (const WallState& w : c.walls) {
    put_string(packer, w.name);
    packer.put(std::vector<Vec3>{w.origin, w.displacement, w.force, w.torque, w.current_velocity});
  }
  for (const auto& [key, value] : c.metadata) {
    put_string(packer, key);
    put_string(packer, value);
  }
}
Checkpoint get_common(Unpacker& unpacker) {
  Checkpoint c;
  const std::vector<double> times = unpacker.get<double>();
  const std::vector<std::int64_t> counts = unpacker.get<std::int64_t>();
  const std::vector<std::uint64_t> sizes = unpacker.get<std::uint64_t>();
  if (times.size() != 2 || counts.size() != 2 || sizes.size() != 2) throw FileError("a damaged checkpoint message");
  c.time = times[0];
  c.time_step = times[1];
  c.stats.steps = counts[0];
  c.stats.rebuilds = counts[1];
  for (std::uint64_t k = 0; k < sizes[0]; ++k) {
    WallState w;
    w.name = get_string(unpacker);
    const std::vector<Vec3> v = unpacker.get<Vec3>();
    if (v.size() != 5) throw FileError("a damaged checkpoint message (wall state)");
    w.origin = v[0];
    w.displacement = v[1];
    w.force = v[2];
    w.torque = v[3];
    w.current_velocity = v[4];
    c.walls.push_back(std::move(w));
  }
  for (std::uint64_t k = 0; k < sizes[1]; ++k) {
    std::string key = get_string(unpacker);
    c.metadata[std::move(key)] = get_string(unpacker);
  }
  return c;
}

// Rank 0's bytes on every rank (sizes first).
void broadcast_bytes(std::vector<char>& bytes, MPI_Comm comm) {
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm);
  bytes.resize(size);
  MPI_Bcast(bytes.data(), int(size), MPI_BYTE, 0, comm);
}

bool by_ids(const HistoryArchive::PairRecord& a, const HistoryArchive::PairRecord& b) {
  return a.low != b.low ? a.low < b.low : a.high < b.high;
}
bool by_particle(const HistoryArchive::WallRecord& a, const HistoryArchive::WallRecord& b) {
  return a.particle != b.particle ? a.particle < b.particle : a.wall < b.wall;
}

}  // namespace

MpiRunRanks::MpiRunRanks(MPI_Comm comm, SlabSettings slabs) : comm_(comm), slabs_(std::move(slabs)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
}

std::unique_ptr<Decomposition> MpiRunRanks::decomposition() {
  auto slab = std::make_unique<SlabDecomposition>(comm_, slabs_);
  slab_ = slab.get();
  return slab;
}

Particles MpiRunRanks::gather(const Simulation& sim) { return gather_particles_on_root(sim, comm_); }

std::size_t MpiRunRanks::particle_count(const Simulation& sim) {
  std::uint64_t count = sim.owned_count();
  MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_UINT64_T, MPI_SUM, comm_);
  return count;
}

// Each rank's state (its particles with the ghosts, its lists, its slab) and its contact
// histories by ids go to rank 0, which writes the whole state: the owned particles of all ranks
// in id order, the histories merged (each pair is listed on one rank only), and the ranks' states.
void MpiRunRanks::save_checkpoint(const std::filesystem::path& path, const Simulation& sim,
                                  const std::map<std::string, std::string>& metadata) {
  if (!slab_) throw InputError("a checkpoint on ranks needs the decomposition attached first");
  RankState mine;
  mine.particles = sim.particles();
  mine.ghosts = sim.particles().size() - sim.owned_count();
  mine.lists = sim.list_state();
  mine.decomposition = slab_->save_state();
  HistoryArchive histories;
  if (!mine.lists.pairs.first.empty()) histories.store_pairs(mine.lists.pairs, mine.particles.id);
  if (!mine.lists.walls.first.empty()) histories.store_walls(mine.lists.walls, mine.particles.id);
  Packer packer;
  packer.put(std::vector<std::uint64_t>{sim.owned_count()});
  put_rank(packer, mine);
  put_histories(packer, histories);
  mine = RankState{};
  std::vector<std::size_t> lengths;
  const std::vector<char> all = gather_bytes_on_root(packer.bytes(), comm_, &lengths);
  on_root(this, [&] {
    Checkpoint c;
    c.metadata = metadata;
    c.time = sim.time();
    c.time_step = sim.time_step();
    c.stats = sim.stats();
    for (const Wall& w : sim.walls()) c.walls.push_back({w.name, w.origin, w.displacement, w.force, w.torque, w.current_velocity});
    c.histories.emplace();
    std::size_t at = 0;
    Particles owned;
    for (std::size_t length : lengths) {
      const std::vector<char> bytes(all.begin() + std::ptrdiff_t(at), all.begin() + std::ptrdiff_t(at + length));
      at += length;
      Unpacker unpacker(bytes);
      const std::vector<std::uint64_t> count = unpacker.get<std::uint64_t>();
      RankState rank = get_rank(unpacker);
      const HistoryArchive h = get_histories(unpacker);
      if (count.size() != 1 || count[0] + rank.ghosts != rank.particles.size())
        throw FileError("a rank's state arrived damaged for the checkpoint");
      for (std::size_t i = 0; i < count[0]; ++i) append_record(owned, record_of(rank.particles, i));
      c.histories->pairs.insert(c.histories->pairs.end(), h.pairs.begin(), h.pairs.end());
      c.histories->walls.insert(c.histories->walls.end(), h.walls.begin(), h.walls.end());
      c.ranks.push_back(std::move(rank));
    }
    std::vector<std::uint32_t> order(owned.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return owned.id[a] < owned.id[b]; });
    owned.permute(order);
    c.particles = std::move(owned);
    std::sort(c.histories->pairs.begin(), c.histories->pairs.end(), by_ids);
    std::sort(c.histories->walls.begin(), c.histories->walls.end(), by_particle);
    write_checkpoint(path, c);
  });
}

std::map<std::string, std::string> MpiRunRanks::restore_checkpoint(std::optional<Checkpoint> on_root_checkpoint,
                                                                    Simulation& sim) {
  if (!slab_) throw InputError("a resume on ranks needs the decomposition attached first");
  // Rank 0 tells how: each rank's own state on the same rank count, else the whole state for all.
  std::vector<char> common;
  bool same_ranks = false;
  if (rank_ == 0) {
    const Checkpoint& c = *on_root_checkpoint;
    same_ranks = c.ranks.size() == std::size_t(ranks_);
    Packer packer;
    packer.put(std::vector<std::uint8_t>{same_ranks ? std::uint8_t(1) : std::uint8_t(0)});
    put_common(packer, c);
    common = std::move(packer.bytes());
  }
  broadcast_bytes(common, comm_);
  Unpacker unpacker(common);
  const std::vector<std::uint8_t> mode = unpacker.get<std::uint8_t>();
  same_ranks = !mode.empty() && mode[0] == 1;
  Checkpoint c = get_common(unpacker);

  std::vector<char> own;
  if (same_ranks) {
    if (rank_ == 0) {
      for (int r = ranks_ - 1; r >= 0; --r) {
        Packer packer;
        put_rank(packer, on_root_checkpoint->ranks[std::size_t(r)]);
        if (r == 0) {
          own = std::move(packer.bytes());
          break;
        }
        const std::uint64_t size = packer.bytes().size();
        MPI_Send(&size, 1, MPI_UINT64_T, r, 301, comm_);
        MPI_Send(packer.bytes().data(), int(size), MPI_BYTE, r, 302, comm_);
      }
    } else {
      std::uint64_t size = 0;
      MPI_Recv(&size, 1, MPI_UINT64_T, 0, 301, comm_, MPI_STATUS_IGNORE);
      own.resize(size);
      MPI_Recv(own.data(), int(size), MPI_BYTE, 0, 302, comm_, MPI_STATUS_IGNORE);
    }
  } else {
    if (rank_ == 0) {
      Packer packer;
      put_particles(packer, on_root_checkpoint->particles);
      put_histories(packer, on_root_checkpoint->histories ? *on_root_checkpoint->histories : HistoryArchive{});
      own = std::move(packer.bytes());
    }
    broadcast_bytes(own, comm_);
  }
  on_root_checkpoint.reset();
  agreed(this, [&] {
    restore_walls(sim, c);
    Unpacker state(own);
    if (same_ranks) {
      RankState rank = get_rank(state);
      const std::size_t n = rank.particles.size();
      const bool lists_match = rank.lists.position_at_build.size() == n && rank.lists.pairs.first.size() == n + 1;
      sim.particles_mutable() = std::move(rank.particles);
      sim.restore(c.time, c.stats, std::move(rank.lists), rank.ghosts);
      slab_->restore_state(rank.decomposition);
      if (!lists_match) sim.particles_mutable();  // the next step rebuilds, as one process would
      return;
    }
    Particles all = get_particles(state);
    HistoryArchive histories = get_histories(state);
    if (c.stats.steps == 0 && c.stats.rebuilds == 0) {
      if (!all.empty())
        throw InputError("checkpoint: a run that never stepped, with particles, resumed on another rank count: start "
                         "it again instead");
      return;
    }
    sim.particles_mutable() = std::move(all);
    sim.resume_from_histories(c.time, c.stats, std::move(histories));
  });
  return c.metadata;
}

void MpiRunRanks::agree(std::exception_ptr local) {
  enum Kind : int { kInput = 1, kSimulation, kFile, kOther };
  int kind = 0;
  std::string message;
  if (local) {
    try {
      std::rethrow_exception(local);
    } catch (const InputError& e) {
      kind = kInput, message = e.what();
    } catch (const SimulationError& e) {
      kind = kSimulation, message = e.what();
    } catch (const FileError& e) {
      kind = kFile, message = e.what();
    } catch (const std::exception& e) {
      kind = kOther, message = e.what();
    } catch (...) {
      kind = kOther, message = "an unknown error";
    }
  }
  int first = local ? rank_ : ranks_;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm_);
  if (first == ranks_) return;
  std::uint64_t length = message.size();
  MPI_Bcast(&kind, 1, MPI_INT, first, comm_);
  MPI_Bcast(&length, 1, MPI_UINT64_T, first, comm_);
  message.resize(length);
  MPI_Bcast(message.data(), int(length), MPI_CHAR, first, comm_);
  note_agreed_failure();
  if (rank_ == first) std::rethrow_exception(local);
  const std::string text = first == 0 ? message : fmt::format("rank {} of {}: {}", first, ranks_, message);
  switch (kind) {
    case kInput: throw InputError(text);
    case kSimulation: throw SimulationError(text);
    case kFile: throw FileError(text);
    default: throw std::runtime_error(text);
  }
}

bool MpiRunRanks::broadcast(bool root_value) {
  int value = root_value ? 1 : 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, comm_);
  return value != 0;
}

bool MpiRunRanks::any(bool local) {
  int flag = local ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_LOR, comm_);
  return flag != 0;
}

std::vector<double> MpiRunRanks::gather_on_root(const std::vector<double>& values) {
  std::vector<double> all(rank_ == 0 ? values.size() * std::size_t(ranks_) : 0);
  MPI_Gather(values.data(), int(values.size()), MPI_DOUBLE, all.data(), int(values.size()), MPI_DOUBLE, 0, comm_);
  return all;
}

}  // namespace trapdem
