#include "dem/threaded_cpu/pair_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "dem/threaded_cpu/batch_lane.hpp"
#include "dem/contact/law_dispatch.hpp"
#include "dem/pair_list.hpp"

namespace trapdem {

namespace {

// The contact law over a batch of touching pairs: one loop over the contacts with no branch the
// compiler cannot turn into selects, so that it runs several contacts per instruction (4 with
// AVX2, 8 with AVX-512). The law's choices are a template argument, resolved at compile time:
// GCC neither if-converts a loop-invariant three-way branch nor vectorises a select on a
// loop-invariant flag. `#pragma omp simd` does not work here with GCC 12 (it turns the law's Vec3
// temporaries into per-lane arrays and gives up).
struct PairBatchLaw {
  using Fn = PairBatchLawFn;
  template <LawChoices kLaw>
  static void run(ContactBatch& batch, std::uint32_t count, const LawParams& law_params, const BodyArrays& body,
                  const PairHistoryRead& history_in, double dt) {
    const LawParams p = law_params;  // a local copy: the loop's stores cannot alias it
    const PairHistoryRead history = history_in;
    const double* __restrict r = body.radius;
    const double* __restrict m = body.mass;
    const double* __restrict inv_i = body.inv_inertia;
    const Vec3* __restrict v = body.velocity;
    const Vec3* __restrict w = body.angular_velocity;
    // The batch's output arrays never overlap what the loop reads.
#pragma GCC ivdep
    for (std::uint32_t q = 0; q < count; ++q) {
      const std::uint32_t i = batch.owner[q], j = batch.partner[q];
      const Vec3 d{batch.separation[0][q], batch.separation[1][q], batch.separation[2][q]};
      const double ri = r[i], rj = r[j];
      const double reach = ri + rj;
      const double dist = std::sqrt(norm2(d));
      const Vec3 normal = d * (1.0 / dist);
      const double overlap = reach - dist;
      batch.overlap_ratio[q] = overlap / std::min(ri, rj);
      const ContactBodies b =
          reduce_bodies<kLaw, SecondBody::sphere>(Body{m[i], ri, inv_i[i]}, Body{m[j], rj, inv_i[j]}, overlap, dist);
      ContactHistory h = load_history<kLaw>(history, batch.history_in[q]);
      const ContactForce cf = ContactEvaluator<kLaw>::evaluate(p, b, normal, overlap, v[i] - v[j], w[i], w[j], h, dt);
      const ContactTorques torques = contact_torques(cf, b, normal);
      store_in_lane(batch, q, cf.force, h);
      batch.torque_owner[0][q] = torques.on_i.x;
      batch.torque_owner[1][q] = torques.on_i.y;
      batch.torque_owner[2][q] = torques.on_i.z;
      batch.torque_partner[0][q] = torques.on_j.x;
      batch.torque_partner[1][q] = torques.on_j.y;
      batch.torque_partner[2][q] = torques.on_j.z;
    }
  }
};

// collect_touching: appends the touching pairs from `at` on to the empty batch until the batch is
// full or the owners up to `end` are done; returns how many it appended. Every listed pair is written to the
// batch and kept only when touching (no branch on touching, which is at random). A pair that
// stopped touching loses its history (its index becomes kNoContact); one that has just formed
// reads the empty entry `no_history`. `next_contact` is where the next contact's history goes. A
// function of its own, with no call inside, so that its few live values stay in registers.
// The sweep first touches a particle's data as the highest partner of an earlier owner, at no
// fixed stride from the owner: the hardware prefetcher does not see it coming, and beyond the last
// level cache (80k particles) every first touch waits for memory. So the data the law will read,
// and the force and torque the shares will add to, just past the owner's highest partner are
// prefetched. The contact histories are read through the batch law's gathers and written in
// add_batch_shares, both about in pair order: without help, each of their cache lines beyond the
// last level cache was a wait for memory (the 80k benchmark ran ~30 % slower per particle than the
// 20k one). They are prefetched kHistoryAhead contacts ahead of the one being collected.
constexpr std::uint32_t kHistoryAhead = 24;  // contacts; 24-48 measured alike at 80k, 96 less good

template <bool kPeriodic>
std::uint32_t collect_touching_in(PairCursor& at, std::size_t end, const Vec3* __restrict x,
                                  const double* __restrict r, const PairSweepLists& lists,
                                  std::uint32_t& next_contact, const Domain& dom, ContactBatch& __restrict batch,
                                  const SweepPrefetch& ahead_of, std::size_t n) {
  const std::uint32_t* __restrict first = lists.first;
  const std::uint32_t* __restrict partner = lists.partner;
  std::uint32_t* __restrict pair_contact = lists.pair_contact;
  const std::uint32_t no_history = lists.no_history;
  std::uint32_t next = next_contact;
  std::uint32_t count = 0;
  batch.history_out = next;
  for (std::size_t i = at.owner; i < end; ++i) {
    const Vec3 xi = x[i];
    const double ri = r[i];
    const std::uint32_t last = first[i + 1];
    if (last > first[i]) {
      const std::size_t ahead = std::min<std::size_t>(partner[last - 1] + 8, n - 1);
      __builtin_prefetch(&x[ahead]);
      __builtin_prefetch(&ahead_of.velocity[ahead]);
      __builtin_prefetch(&ahead_of.angular_velocity[ahead]);
      __builtin_prefetch(&ahead_of.force[ahead], 1);
      __builtin_prefetch(&ahead_of.torque[ahead], 1);
    }
    for (std::uint32_t k = std::max(at.pair, first[i]); k < last; ++k) {
      const std::uint32_t j = partner[k];
      Vec3 d = xi - x[j];
      if constexpr (kPeriodic) d = dom.minimum_image(d);
      const double reach = ri + r[j];
      const bool touching = norm2(d) < reach * reach;
      const std::uint32_t last_step = pair_contact[k];
      pair_contact[k] = touching ? next : kNoContact;
      batch.owner[count] = std::uint32_t(i);
      batch.partner[count] = j;
      batch.history_in[count] = last_step == kNoContact ? no_history : last_step;
      batch.separation[0][count] = d.x;
      batch.separation[1][count] = d.y;
      batch.separation[2][count] = d.z;
      count += touching ? 1u : 0u;
      next += touching ? 1u : 0u;
      const std::uint32_t history_ahead = std::min(next + kHistoryAhead, no_history);
      __builtin_prefetch(&ahead_of.history.tangential[history_ahead]);
      __builtin_prefetch(&ahead_of.next_history.tangential[history_ahead], 1);
      if (ahead_of.history.rolling) {  // the same for every pair (the law's choice): predicted
        __builtin_prefetch(&ahead_of.history.rolling[history_ahead]);
        __builtin_prefetch(&ahead_of.next_history.rolling[history_ahead], 1);
      }
      if (count == ContactBatch::kCapacity) {
        at = {i, k + 1};
        next_contact = next;
        return count;
      }
    }
  }
  at = {end, 0};
  next_contact = next;
  return count;
}

}  // namespace

PairBatchLawFn pair_batch_law(const LawChoices& choices) { return law_instance<PairBatchLaw>(choices); }

std::uint32_t collect_touching(PairCursor& at, std::size_t end, const Vec3* __restrict x, const double* __restrict r,
                               const PairSweepLists& lists, std::uint32_t& next_contact, const Domain& dom,
                               bool periodic, ContactBatch& __restrict batch, const SweepPrefetch& ahead_of,
                               std::size_t n) {
  return periodic ? collect_touching_in<true>(at, end, x, r, lists, next_contact, dom, batch, ahead_of, n)
                  : collect_touching_in<false>(at, end, x, r, lists, next_contact, dom, batch, ahead_of, n);
}

void add_batch_shares(const ContactBatch& __restrict batch, std::uint32_t count, std::size_t end, Vec3* __restrict f,
                      Vec3* __restrict t, const PairHistoryWrite& history, OwnerSums& sums,
                      std::vector<PartnerShare>& later, double& max_overlap) {
  for (std::uint32_t q = 0; q < count; ++q) {
    const std::uint32_t i = batch.owner[q], j = batch.partner[q];
    if (i != sums.owner) {
      f[sums.owner] += sums.force;
      t[sums.owner] += sums.torque;
      sums = {i, Vec3{}, Vec3{}};
    }
    max_overlap = std::max(max_overlap, batch.overlap_ratio[q]);
    const std::uint32_t out = batch.history_out + q;
    history.tangential[out] = {{batch.spring[0][q], batch.spring[1][q], batch.spring[2][q]}, batch.flags[q]};
    if (history.rolling)  // the same for every pair (the law's choice): predicted
      history.rolling[out] = {batch.rolling_spring[0][q], batch.rolling_spring[1][q], batch.rolling_spring[2][q]};
    const Vec3 force{batch.force[0][q], batch.force[1][q], batch.force[2][q]};
    sums.force += force;
    sums.torque += Vec3{batch.torque_owner[0][q], batch.torque_owner[1][q], batch.torque_owner[2][q]};
    const Vec3 tj{batch.torque_partner[0][q], batch.torque_partner[1][q], batch.torque_partner[2][q]};
    if (j < end) {
      f[j] -= force;
      t[j] += tj;
    } else {
      later.push_back({j, -force, tj});
    }
  }
}

}  // namespace trapdem
