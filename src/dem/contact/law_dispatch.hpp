#pragma once
// The law's template instances, generated from the choices' tables (choices.hpp): every
// combination of the choices' values is numbered (mixed radix), and a table of the batch
// loops' instances, one per number, is built at compile time; combinations that differ only in
// choices their rolling model ignores share an instance (LawChoices::canonical). A new value of a
// choice adds its instances here without an edit. The instance is looked up once per batch loop
// call, never per contact.
#include <array>
#include <cstddef>
#include <utility>

#include "dem/contact/choices.hpp"

namespace trapdem {

namespace law_dispatch_detail {

inline constexpr std::size_t kLawCount = kChoiceCount<NormalModel> * kChoiceCount<RollingModel> *
                                         kChoiceCount<RollingLeverArm> * kChoiceCount<RollingStiffness> * 2;

constexpr std::size_t number_of(const LawChoices& c) {
  std::size_t k = static_cast<std::size_t>(c.normal);
  k = k * kChoiceCount<RollingModel> + static_cast<std::size_t>(c.rolling);
  k = k * kChoiceCount<RollingLeverArm> + static_cast<std::size_t>(c.lever_arm);
  k = k * kChoiceCount<RollingStiffness> + static_cast<std::size_t>(c.rolling_stiffness);
  return k * 2 + (c.rolling_dashpot ? 1 : 0);
}

constexpr LawChoices choices_numbered(std::size_t k) {
  LawChoices c;
  c.rolling_dashpot = k % 2 == 1;
  k /= 2;
  c.rolling_stiffness = static_cast<RollingStiffness>(k % kChoiceCount<RollingStiffness>);
  k /= kChoiceCount<RollingStiffness>;
  c.lever_arm = static_cast<RollingLeverArm>(k % kChoiceCount<RollingLeverArm>);
  k /= kChoiceCount<RollingLeverArm>;
  c.rolling = static_cast<RollingModel>(k % kChoiceCount<RollingModel>);
  k /= kChoiceCount<RollingModel>;
  c.normal = static_cast<NormalModel>(k);
  return c;
}

// The numbering is a bijection over the combinations.
constexpr bool numbering_round_trips() {
  for (std::size_t k = 0; k < kLawCount; ++k)
    if (number_of(choices_numbered(k)) != k) return false;
  return true;
}
static_assert(numbering_round_trips());

}  // namespace law_dispatch_detail

// The instance of a batch loop for the law's choices. `Loop` is a struct with a function-pointer
// type `Fn` and a static function template `run<LawChoices>` of that type.
template <class Loop>
typename Loop::Fn law_instance(const LawChoices& choices) {
  using namespace law_dispatch_detail;
  static constexpr auto table = []<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Loop::Fn, kLawCount>{&Loop::template run<choices_numbered(K).canonical()>...};
  }(std::make_index_sequence<kLawCount>{});
  return table[number_of(choices)];
}

}  // namespace trapdem
