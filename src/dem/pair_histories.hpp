#pragma once
// The touching pairs' contact histories in the engine's compact form (Simulation): a structure of
// arrays, so that a law without a rolling spring moves only what it keeps. The seed's
// constant-torque rolling (eq. 5) and no rolling keep the tangential spring and the flags, 32 B a
// contact; the EPSD rolling model keeps its rolling spring too, in an array of its own (24 B more).
// At 300k particles every step reads each contact's history and writes it anew, and the histories
// were a third of a step's memory traffic with the rolling spring stored for every law
// (bench/RESULTS.md, 2026-12-02). Tools and checkpoints see a ContactHistory either way.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "dem/contact/choices.hpp"
#include "dem/contact/models.hpp"  // keeps_rolling_spring
#include "dem/contact/contact_history.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// What every law remembers of a contact.
struct TangentialHistory {
  Vec3 spring;               // m, ContactHistory::tangential_spring
  std::uint32_t flags = 0;   // ContactHistory::flags
};

// The histories as the batch loops read them (rolling is null for a law without a rolling spring).
struct PairHistoryRead {
  const TangentialHistory* __restrict tangential;
  const Vec3* __restrict rolling;
};
// ... and write them.
struct PairHistoryWrite {
  TangentialHistory* __restrict tangential;
  Vec3* __restrict rolling;
};

// Contact k's history for a law of choices kLaw (whose rolling spring, if it keeps none, is zero).
template <LawChoices kLaw>
[[gnu::always_inline]] inline ContactHistory load_history(const PairHistoryRead& from, std::uint32_t k) {
  ContactHistory h;
  h.tangential_spring = from.tangential[k].spring;
  h.flags = from.tangential[k].flags;
  if constexpr (keeps_rolling_spring(kLaw)) h.rolling_spring = from.rolling[k];
  return h;
}

class PairHistories {
 public:
  explicit PairHistories(bool rolling_spring = false) : rolling_spring_(rolling_spring) {}

  bool has_rolling_spring() const { return rolling_spring_; }
  std::size_t size() const { return tangential_.size(); }
  // Room for n histories; grown only (the pages of a larger earlier list stay), new entries empty.
  void grow_to(std::size_t n) {
    if (tangential_.size() >= n) return;
    tangential_.resize(n);
    if (rolling_spring_) rolling_.resize(n);
  }

  ContactHistory get(std::size_t k) const {
    ContactHistory h;
    h.tangential_spring = tangential_[k].spring;
    h.flags = tangential_[k].flags;
    if (rolling_spring_) h.rolling_spring = rolling_[k];
    return h;
  }
  // A law without a rolling spring drops h's (zero for such a law's contacts).
  void set(std::size_t k, const ContactHistory& h) {
    tangential_[k] = {h.tangential_spring, h.flags};
    if (rolling_spring_) rolling_[k] = h.rolling_spring;
  }

  PairHistoryRead read() const { return {tangential_.data(), rolling_spring_ ? rolling_.data() : nullptr}; }
  PairHistoryWrite write() { return {tangential_.data(), rolling_spring_ ? rolling_.data() : nullptr}; }
  void swap(PairHistories& other) noexcept {
    tangential_.swap(other.tangential_);
    rolling_.swap(other.rolling_);
    std::swap(rolling_spring_, other.rolling_spring_);
  }

 private:
  bool rolling_spring_;
  std::vector<TangentialHistory> tangential_;
  std::vector<Vec3> rolling_;
};

}  // namespace trapdem
