#pragma once
// The law's template instances, generated from the choices' axes (LawAxes, choices.hpp): every
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

// The numbering is a bijection over the combinations.
constexpr bool law_numbering_round_trips() {
  for (std::size_t k = 0; k < LawAxes::kCount; ++k)
    if (LawAxes::number_of(LawAxes::numbered(k)) != k) return false;
  return true;
}
static_assert(law_numbering_round_trips());

// The instance of a batch loop for the law's choices. `Loop` is a struct with a function-pointer
// type `Fn` and a static function template `run<LawChoices>` of that type.
template <class Loop>
typename Loop::Fn law_instance(const LawChoices& choices) {
  static constexpr auto table = []<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Loop::Fn, LawAxes::kCount>{&Loop::template run<LawAxes::numbered(K).canonical()>...};
  }(std::make_index_sequence<LawAxes::kCount>{});
  return table[LawAxes::number_of(choices)];
}

}  // namespace trapdem
