#pragma once
// A list of the models of one sub-model axis (normal, tangential, rolling), in the order of its
// choice's enum and table (choices.hpp), checked at compile time: a value without a model, or a
// model in the wrong place, does not compile. The list maps a choice to its model at compile time
// (Model<value>) and at run time (visit), and holds every model's parameters (Params).
#include <cstddef>
#include <tuple>

#include "dem/contact/choices.hpp"

namespace trapdem {

template <class Enum, class... Models>
struct ModelList {
  static constexpr bool lists_every_value_in_order() {
    constexpr Enum listed[] = {Models::model...};
    if (sizeof...(Models) != kChoiceCount<Enum>) return false;
    for (std::size_t k = 0; k < sizeof...(Models); ++k)
      if (listed[k] != ChoiceTable<Enum>::values[k].value) return false;
    return true;
  }
  static_assert(lists_every_value_in_order(), "a model per value of the choice, in the enum's order");

  // Each model's parameters, one base each (a trivially copyable block of doubles, unlike a
  // std::tuple: WallLaws copies it as such): static_cast<const Model::Params&>(params).
  struct Params : Models::Params... {};

  template <Enum m>
  using Model = std::tuple_element_t<static_cast<std::size_t>(m), std::tuple<Models...>>;

  // f(Model{}) for every model, in the list's order.
  template <class F>
  static constexpr void for_each(F&& f) {
    (f(Models{}), ...);
  }

  // f(Model{}) for the model of value m (a run-time choice: parameters, time step, inertias).
  template <class F>
  static constexpr auto visit(Enum m, F&& f) {
    using R = decltype(f(std::tuple_element_t<0, std::tuple<Models...>>{}));
    R result{};
    ((m == Models::model ? (void)(result = f(Models{})) : (void)0), ...);
    return result;
  }
};

}  // namespace trapdem
