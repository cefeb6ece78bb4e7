#pragma once
// Particle pairs (engine-private): the listed pairs of a thread's block tested for touching and
// the touching ones gathered in a batch, the law run over the batch as one vectorised loop, the
// batch's shares added in pair order.
#include <cstdint>
#include <vector>

#include "dem/threaded_cpu/batch_lane.hpp"
#include "dem/contact/law.hpp"
#include "dem/domain.hpp"
#include "dem/pair_histories.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The touching pairs of a stretch of a thread's block, gathered so that the contact law runs over
// them as one vectorisable loop (structure of arrays, contact-major).
struct ContactBatch {
  static constexpr std::uint32_t kCapacity = 64;
  alignas(64) std::uint32_t owner[kCapacity];
  alignas(64) std::uint32_t partner[kCapacity];
  alignas(64) std::uint32_t history_in[kCapacity];   // index of the pair's history of the last step
  // Where contact q's history of this step goes: history_out + q (the touching pairs' histories
  // are written in pair order, one after the other).
  std::uint32_t history_out = 0;
  alignas(64) double separation[3][kCapacity];  // m, x_owner - x_partner (minimum image)
  alignas(64) double overlap_ratio[kCapacity];  // overlap / smaller radius
  alignas(64) double force[3][kCapacity];       // N, on the owner
  alignas(64) double torque_owner[3][kCapacity], torque_partner[3][kCapacity];  // N m
  alignas(64) double spring[3][kCapacity], rolling_spring[3][kCapacity];       // the new history
  alignas(64) std::uint32_t flags[kCapacity];
};

// A pair's share for a partner in a later thread's block, added after the sweep.
struct PartnerShare {
  std::uint32_t particle;
  Vec3 force, torque;
};

// The law over the batch's first `count` contacts, compiled for the law's choices (law_instance).
using PairBatchLawFn = void (*)(ContactBatch&, std::uint32_t, const LawParams&, const BodyArrays&,
                                const PairHistoryRead&, double);
PairBatchLawFn pair_batch_law(const LawChoices& choices);

// Where collect_touching() stopped: the owner and its next listed pair.
struct PairCursor {
  std::size_t owner;
  std::uint32_t pair;
};

// What the sweep prefetches (see collect_touching).
struct SweepPrefetch {
  const Vec3* velocity;
  const Vec3* angular_velocity;
  const Vec3* force;
  const Vec3* torque;
  PairHistoryRead history;        // last step's, read by the batch law
  PairHistoryWrite next_history;  // this step's, written by add_batch_shares
};

// The pair list and the compact histories as collect_touching reads and writes them.
struct PairSweepLists {
  const std::uint32_t* __restrict first;
  const std::uint32_t* __restrict partner;
  std::uint32_t* __restrict pair_contact;  // per listed pair: index into the compact histories, or kNoContact
  std::uint32_t no_history;                // the compact arrays' empty last entry
};

// Appends the touching pairs from `at` on to the empty batch until the batch is full or the
// owners up to `end` are done; returns how many it appended (see pair_sweep.cpp).
std::uint32_t collect_touching(PairCursor& at, std::size_t end, const Vec3* __restrict x, const double* __restrict r,
                               const PairSweepLists& lists, std::uint32_t& next_contact, const Domain& dom,
                               bool periodic, ContactBatch& __restrict batch, const SweepPrefetch& ahead_of,
                               std::size_t n);

// A thread's running sums for the owner whose pairs are being added.
struct OwnerSums {
  std::size_t owner;
  Vec3 force, torque;
};

// Stores the batch's histories and adds its forces and torques in pair order: the partner's share
// at once (or, for a partner at or beyond `end`, in `later`), the owner's summed until its last pair.
void add_batch_shares(const ContactBatch& __restrict batch, std::uint32_t count, std::size_t end, Vec3* __restrict f,
                      Vec3* __restrict t, const PairHistoryWrite& history, OwnerSums& sums,
                      std::vector<PartnerShare>& later, double& max_overlap);

}  // namespace trapdem
