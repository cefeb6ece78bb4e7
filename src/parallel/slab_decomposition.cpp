#include "parallel/slab_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "parallel/failure_agreement.hpp"
#include "parallel/particle_record.hpp"

namespace trapdem {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
enum Side { kLeft = 0, kRight = 1 };
enum Tag { kSizeTag = 101, kBytesTag, kGhostStateTag, kGhostForceTag };

// Both neighbours' messages at once (a rank at an end has MPI_PROC_NULL there: nothing moves).
// Sizes first, then the bytes.
void exchange_bytes(MPI_Comm comm, const int neighbour[2], std::vector<char> out[2], std::vector<char> in[2]) {
  std::uint64_t out_size[2] = {out[0].size(), out[1].size()}, in_size[2] = {0, 0};
  MPI_Request req[4];
  for (int s = 0; s < 2; ++s) {
    MPI_Irecv(&in_size[s], 1, MPI_UINT64_T, neighbour[s], kSizeTag, comm, &req[2 * s]);
    MPI_Isend(&out_size[s], 1, MPI_UINT64_T, neighbour[s], kSizeTag, comm, &req[2 * s + 1]);
  }
  MPI_Waitall(4, req, MPI_STATUSES_IGNORE);
  for (int s = 0; s < 2; ++s) {
    in[s].resize(in_size[s]);
    MPI_Irecv(in[s].data(), int(in_size[s]), MPI_BYTE, neighbour[s], kBytesTag, comm, &req[2 * s]);
    MPI_Isend(out[s].data(), int(out_size[s]), MPI_BYTE, neighbour[s], kBytesTag, comm, &req[2 * s + 1]);
  }
  MPI_Waitall(4, req, MPI_STATUSES_IGNORE);
}

// Doubles of known counts with both neighbours.
void exchange_doubles(MPI_Comm comm, const int neighbour[2], int tag, std::vector<double> out[2],
                      std::vector<double> in[2]) {
  MPI_Request req[4];
  for (int s = 0; s < 2; ++s) {
    MPI_Irecv(in[s].data(), int(in[s].size()), MPI_DOUBLE, neighbour[s], tag, comm, &req[2 * s]);
    MPI_Isend(out[s].data(), int(out[s].size()), MPI_DOUBLE, neighbour[s], tag, comm, &req[2 * s + 1]);
  }
  MPI_Waitall(4, req, MPI_STATUSES_IGNORE);
}

void put_vec3(double*& at, const Vec3& v) {
  at[0] = v.x;
  at[1] = v.y;
  at[2] = v.z;
  at += 3;
}
Vec3 get_vec3(const double*& at) {
  const Vec3 v{at[0], at[1], at[2]};
  at += 3;
  return v;
}

bool contains(const std::vector<std::int64_t>& sorted, std::int64_t id) {
  return std::binary_search(sorted.begin(), sorted.end(), id);
}

}  // namespace

SlabDecomposition::SlabDecomposition(MPI_Comm comm, SlabSettings settings) : comm_(comm), settings_(std::move(settings)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  if (!settings_.bounds.empty()) {
    if (settings_.bounds.size() != std::size_t(ranks_ - 1))
      throw InputError(fmt::format("slab decomposition: {} boundaries given for {} ranks (expected {})",
                                   settings_.bounds.size(), ranks_, ranks_ - 1));
    if (!std::is_sorted(settings_.bounds.begin(), settings_.bounds.end()))
      throw InputError("slab decomposition: the boundaries must ascend");
  }
  if (!(settings_.rebalance_above > 0.0))
    throw InputError(fmt::format("slab decomposition: rebalance_above must be positive (got {})",
                                 settings_.rebalance_above));
}

int SlabDecomposition::owner_of(double x) const {
  const int r = int(std::upper_bound(bounds_.begin(), bounds_.end(), x) - bounds_.begin()) - 1;
  return std::clamp(r, 0, ranks_ - 1);
}

// Every rank holds the same particles: the boundaries are those given, or the x quantiles
// k N / R (midway between the neighbouring particles) so every rank starts with ~N/R, or with
// fewer particles than ranks (a pour's start) the domain's x in equal slabs.
void SlabDecomposition::adopt(Particles& p, const Domain& domain) {
  bounds_.assign(std::size_t(ranks_) + 1, kInfinity);
  bounds_[0] = -kInfinity;
  if (!settings_.bounds.empty()) {
    std::copy(settings_.bounds.begin(), settings_.bounds.end(), bounds_.begin() + 1);
  } else if (p.size() >= std::size_t(ranks_)) {
    std::vector<double> x(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) x[i] = p.position[i].x;
    std::sort(x.begin(), x.end());
    for (int k = 1; k < ranks_; ++k) {
      const std::size_t at = p.size() * std::size_t(k) / std::size_t(ranks_);
      bounds_[std::size_t(k)] = 0.5 * (x[at - 1] + x[at]);
    }
  } else {
    for (int k = 1; k < ranks_; ++k) bounds_[std::size_t(k)] = domain.lower.x + domain.length(0) * k / ranks_;
  }
  std::vector<std::uint32_t> keep;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    if (owner_of(p.position[i].x) == rank_) keep.push_back(i);
  p.permute(keep);
  p.truncate(keep.size());
}

// The boundaries at the x quantiles k N / R of all ranks' particles, found by bisection on the
// global count of particles below a candidate (one reduction of R - 1 counts per halving): no
// rank gathers the others' positions.
void SlabDecomposition::rebalance(const Particles& p) {
  std::vector<double> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = p.position[i].x;
  std::sort(x.begin(), x.end());
  // -min and max of x over the ranks (a rank without particles adds -inf to both).
  double range[2] = {x.empty() ? -kInfinity : -x.front(), x.empty() ? -kInfinity : x.back()};
  MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MAX, comm_);
  const double x_lo = -range[0], x_hi = range[1];
  std::int64_t total = std::int64_t(p.size());
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_INT64_T, MPI_SUM, comm_);
  const std::size_t inner = std::size_t(ranks_ - 1);
  std::vector<double> lo(inner, x_lo), hi(inner, std::nextafter(x_hi, kInfinity));
  std::vector<std::int64_t> below(inner);
  // Halving the box's extent 60 times leaves an interval far below a particle's size.
  for (int iteration = 0; iteration < 60; ++iteration) {
    for (std::size_t k = 0; k < inner; ++k)
      below[k] = std::lower_bound(x.begin(), x.end(), 0.5 * (lo[k] + hi[k])) - x.begin();
    MPI_Allreduce(MPI_IN_PLACE, below.data(), int(inner), MPI_INT64_T, MPI_SUM, comm_);
    for (std::size_t k = 0; k < inner; ++k) {
      const std::int64_t target = total * std::int64_t(k + 1) / ranks_;
      (below[k] >= target ? hi[k] : lo[k]) = 0.5 * (lo[k] + hi[k]);
    }
  }
  for (std::size_t k = 0; k < inner; ++k) bounds_[k + 1] = hi[k];
  ++rebalances_;
}

void SlabDecomposition::migrate(Particles& p, HistoryArchive& archive, double range) {
  std::int64_t count = std::int64_t(p.size()), largest = count;
  MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_INT64_T, MPI_SUM, comm_);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_INT64_T, MPI_MAX, comm_);
  const double mean = double(count) / ranks_;
  if (ranks_ > 1 && count >= 2 * ranks_ && double(largest) > (1.0 + settings_.rebalance_above) * mean) rebalance(p);
  // One hop per round: a particle whose slab is farther (after a rebalance) is passed on.
  while (any(migrate_one_hop(p, archive))) {
  }
}

bool SlabDecomposition::migrate_one_hop(Particles& p, HistoryArchive& archive) {
  std::vector<std::uint32_t> keep;
  std::vector<ParticleRecord> leaving[2];
  std::vector<std::int64_t> ids[2];
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    const int to = owner_of(p.position[i].x);
    if (to == rank_) {
      keep.push_back(i);
      continue;
    }
    const int side = to < rank_ ? kLeft : kRight;
    leaving[side].push_back(record_of(p, i));
    ids[side].push_back(p.id[i]);
  }
  const bool moved = !leaving[kLeft].empty() || !leaving[kRight].empty();
  for (auto& side_ids : ids) std::sort(side_ids.begin(), side_ids.end());
  // A pair's history goes with the particle of the lower id (the rank that owns it computes the
  // pair, keep_pairs_computed_here); a wall contact's with its particle.
  std::vector<HistoryArchive::PairRecord> pairs[2], pairs_kept;
  std::vector<HistoryArchive::WallRecord> walls[2], walls_kept;
  for (const auto& r : archive.pairs) {
    if (contains(ids[kLeft], r.low)) pairs[kLeft].push_back(r);
    else if (contains(ids[kRight], r.low)) pairs[kRight].push_back(r);
    else pairs_kept.push_back(r);
  }
  for (const auto& r : archive.walls) {
    if (contains(ids[kLeft], r.particle)) walls[kLeft].push_back(r);
    else if (contains(ids[kRight], r.particle)) walls[kRight].push_back(r);
    else walls_kept.push_back(r);
  }
  std::vector<char> out[2], in[2];
  for (int s = 0; s < 2; ++s) {
    Packer packer;
    packer.put(leaving[s]);
    packer.put(pairs[s]);
    packer.put(walls[s]);
    out[s] = std::move(packer.bytes());
  }
  const int neighbour[2] = {rank_ > 0 ? rank_ - 1 : MPI_PROC_NULL, rank_ + 1 < ranks_ ? rank_ + 1 : MPI_PROC_NULL};
  exchange_bytes(comm_, neighbour, out, in);

  if (moved) {
    p.permute(keep);
    p.truncate(keep.size());
  }
  archive.pairs = std::move(pairs_kept);
  archive.walls = std::move(walls_kept);
  for (int s = 0; s < 2; ++s) {  // the left neighbour's first
    if (in[s].empty()) continue;
    Unpacker unpacker(in[s]);
    for (const ParticleRecord& r : unpacker.get<ParticleRecord>()) append_record(p, r);
    for (const auto& r : unpacker.get<HistoryArchive::PairRecord>()) archive.pairs.push_back(r);
    for (const auto& r : unpacker.get<HistoryArchive::WallRecord>()) archive.walls.push_back(r);
  }
  return moved;
}

std::size_t SlabDecomposition::exchange_ghosts(Particles& p, double range) {
  // Ghosts come from the two neighbours only: a slab between two others must span the range, or
  // a particle two slabs away could be within reach and missing.
  for (int r = 1; r + 1 < ranks_; ++r) {
    const double width = bounds_[std::size_t(r) + 1] - bounds_[std::size_t(r)];
    if (!(width >= range))
      throw SimulationError(fmt::format(
          "slab decomposition: rank {}'s slab [{:.6g}, {:.6g}] m is {:.4g} m wide, less than the interaction range "
          "{:.4g} m (twice the largest radius plus the skin): run on fewer ranks",
          r, bounds_[std::size_t(r)], bounds_[std::size_t(r) + 1], width, range));
  }
  owned_ = p.size();
  const double lower = bounds_[std::size_t(rank_)], upper = bounds_[std::size_t(rank_) + 1];
  send_[kLeft].clear();
  send_[kRight].clear();
  for (std::uint32_t i = 0; i < owned_; ++i) {
    const double x = p.position[i].x;
    if (rank_ > 0 && x < lower + range) send_[kLeft].push_back(i);
    if (rank_ + 1 < ranks_ && x >= upper - range) send_[kRight].push_back(i);
  }
  std::vector<char> out[2], in[2];
  for (int s = 0; s < 2; ++s) {
    std::vector<ParticleRecord> records;
    records.reserve(send_[s].size());
    for (std::uint32_t i : send_[s]) records.push_back(record_of(p, i));
    Packer packer;
    packer.put(records);
    out[s] = std::move(packer.bytes());
  }
  const int neighbour[2] = {rank_ > 0 ? rank_ - 1 : MPI_PROC_NULL, rank_ + 1 < ranks_ ? rank_ + 1 : MPI_PROC_NULL};
  exchange_bytes(comm_, neighbour, out, in);
  for (int s = 0; s < 2; ++s) {  // the left neighbour's first
    received_[s] = 0;
    if (in[s].empty()) continue;
    Unpacker unpacker(in[s]);
    for (const ParticleRecord& r : unpacker.get<ParticleRecord>()) {
      append_record(p, r);
      ++received_[s];
    }
  }
  return received_[kLeft] + received_[kRight];
}

// Positions, velocities and angular velocities: 9 doubles per ghost.
void SlabDecomposition::update_ghosts(Particles& p) {
  const int neighbour[2] = {rank_ > 0 ? rank_ - 1 : MPI_PROC_NULL, rank_ + 1 < ranks_ ? rank_ + 1 : MPI_PROC_NULL};
  for (int s = 0; s < 2; ++s) {
    send_buffer_[s].resize(9 * send_[s].size());
    double* at = send_buffer_[s].data();
    for (std::uint32_t i : send_[s]) {
      put_vec3(at, p.position[i]);
      put_vec3(at, p.velocity[i]);
      put_vec3(at, p.angular_velocity[i]);
    }
    receive_buffer_[s].resize(9 * received_[s]);
  }
  exchange_doubles(comm_, neighbour, kGhostStateTag, send_buffer_, receive_buffer_);
  std::size_t g = owned_;
  for (int s = 0; s < 2; ++s) {
    const double* at = receive_buffer_[s].data();
    for (std::size_t k = 0; k < received_[s]; ++k, ++g) {
      p.position[g] = get_vec3(at);
      p.velocity[g] = get_vec3(at);
      p.angular_velocity[g] = get_vec3(at);
    }
  }
}

// Forces and torques: 6 doubles per ghost, back to the rank it came from; each rank adds its
// left neighbour's shares, then its right neighbour's.
void SlabDecomposition::return_ghost_forces(Particles& p) {
  const int neighbour[2] = {rank_ > 0 ? rank_ - 1 : MPI_PROC_NULL, rank_ + 1 < ranks_ ? rank_ + 1 : MPI_PROC_NULL};
  std::size_t g = owned_;
  for (int s = 0; s < 2; ++s) {
    send_buffer_[s].resize(6 * received_[s]);
    double* at = send_buffer_[s].data();
    for (std::size_t k = 0; k < received_[s]; ++k, ++g) {
      put_vec3(at, p.force[g]);
      put_vec3(at, p.torque[g]);
    }
    receive_buffer_[s].resize(6 * send_[s].size());
  }
  exchange_doubles(comm_, neighbour, kGhostForceTag, send_buffer_, receive_buffer_);
  for (int s = 0; s < 2; ++s) {
    const double* at = receive_buffer_[s].data();
    for (std::uint32_t i : send_[s]) {
      p.force[i] += get_vec3(at);
      p.torque[i] += get_vec3(at);
    }
  }
}

bool SlabDecomposition::any(bool local) {
  int flag = local ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_LOR, comm_);
  return flag != 0;
}

void SlabDecomposition::max(double* values, int count) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_MAX, comm_);
}

// Gathered and added in rank order (MPI_Allreduce may add in any order).
double SlabDecomposition::sum(double local) {
  std::vector<double> all(static_cast<std::size_t>(ranks_));
  MPI_Allgather(&local, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, comm_);
  double total = 0.0;
  for (double v : all) total += v;
  return total;
}

void SlabDecomposition::sum_wall_loads(std::vector<Wall>& walls) {
  const std::size_t n = walls.size();
  if (n == 0) return;
  std::vector<double> mine(6 * n), all(6 * n * std::size_t(ranks_));
  double* at = mine.data();
  for (const Wall& w : walls) {
    put_vec3(at, w.force);
    put_vec3(at, w.torque);
  }
  MPI_Allgather(mine.data(), int(6 * n), MPI_DOUBLE, all.data(), int(6 * n), MPI_DOUBLE, comm_);
  for (Wall& w : walls) w.force = w.torque = Vec3{};
  for (int r = 0; r < ranks_; ++r) {
    const double* from = all.data() + 6 * n * std::size_t(r);
    for (Wall& w : walls) {
      w.force += get_vec3(from);
      w.torque += get_vec3(from);
    }
  }
}

void SlabDecomposition::agree_on_failure(const std::string& message) {
  int first = message.empty() ? ranks_ : rank_;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm_);
  if (first == ranks_) return;
  std::uint64_t length = message.size();
  MPI_Bcast(&length, 1, MPI_UINT64_T, first, comm_);
  std::string text = rank_ == first ? message : std::string(length, ' ');
  MPI_Bcast(text.data(), int(length), MPI_CHAR, first, comm_);
  note_agreed_failure();
  throw SimulationError(fmt::format("rank {} of {}: {}", first, ranks_, text));
}

std::vector<std::uint8_t> SlabDecomposition::save_state() const {
  Packer packer;
  packer.put(bounds_);
  packer.put(std::vector<std::int64_t>{balance_at_next_rebuild_ ? 1 : 0, rebalances_, std::int64_t(received_[kLeft]),
                                       std::int64_t(received_[kRight]), std::int64_t(owned_)});
  packer.put(send_[kLeft]);
  packer.put(send_[kRight]);
  const std::vector<char>& bytes = packer.bytes();
  return {bytes.begin(), bytes.end()};
}

void SlabDecomposition::restore_state(const std::vector<std::uint8_t>& state) {
  const std::vector<char> bytes(state.begin(), state.end());
  Unpacker unpacker(bytes);
  std::vector<double> bounds = unpacker.get<double>();
  const std::vector<std::int64_t> counts = unpacker.get<std::int64_t>();
  if (bounds.size() != std::size_t(ranks_) + 1 || counts.size() != 5)
    throw InputError(fmt::format("slab decomposition: a checkpointed state of {} boundaries for {} ranks",
                                 bounds.size(), ranks_));
  bounds_ = std::move(bounds);
  balance_at_next_rebuild_ = counts[0] != 0;
  rebalances_ = counts[1];
  received_[kLeft] = std::size_t(counts[2]);
  received_[kRight] = std::size_t(counts[3]);
  owned_ = std::size_t(counts[4]);
  send_[kLeft] = unpacker.get<std::uint32_t>();
  send_[kRight] = unpacker.get<std::uint32_t>();
}

SlabDecomposition& decompose_in_slabs(Simulation& sim, MPI_Comm comm, SlabSettings settings) {
  auto slabs = std::make_unique<SlabDecomposition>(comm, std::move(settings));
  SlabDecomposition& ref = *slabs;
  sim.set_decomposition(std::move(slabs));
  return ref;
}

}  // namespace trapdem
