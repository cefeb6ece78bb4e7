#pragma once
// The contact law's choices: one enum class per sub-model choice, each with its table of
// configuration names. The table is the list of the enum's values: the law's template instances
// (law_dispatch.hpp), the configuration parser and to_string() are generated from it, so a new
// value is added in two places side by side (the enum and its table) and nowhere else.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace trapdem {

enum class NormalModel {
  linear,  // F_n = k_n delta (the seed paper's eq. 1)
  hertz,   // F_n = 4/3 E* sqrt(R*) delta^3/2 with Mindlin's tangential stiffness (normal_hertz.hpp)
};

enum class TangentialModel {
  coulomb,        // incremental spring-dashpot capped by static/kinetic Coulomb friction (seed eq. 2)
  blaze_viscous,  // Blaze-DEM's public code: a viscous force without spring or Coulomb cap (tangential_blaze_viscous.hpp)
  blaze_tresca,   // the strength Blaze's force makes, as a spring capped at it: stable at any step (tangential_blaze_tresca.hpp)
};

enum class RollingModel {
  none,
  constant_torque,   // Ai et al. (2011) type A: M = mu_r R |F_n| opposing the relative rolling (seed eq. 5)
  elastic_plastic,   // Ai et al. (2011) type C (EPSD): spring torque capped at mu_r R |F_n|, dashpot below it
  angular_damping,   // Blaze-DEM's public code: omega <- omega (1 - mu_r) per reference step (rolling_angular_damping.hpp)
};

enum class DampingModel {
  restitution,        // c_n from e (damping.hpp)
  restitution_blaze,  // the same with e lowered by 0.03808 for 0.3 <= e <= 0.9, as Blaze-DEM's input reader does
};

enum class RollingLeverArm {
  average_radius,    // R = (r_i + r_j) / 2, the seed paper's "average particle radius"
  effective_radius,  // R = r_i r_j / (r_i + r_j), Ai et al. (2011) and LIGGGHTS; half as large for equal spheres
};

enum class RollingStiffness {
  ai2011,            // k_r = 2.25 k_n mu_r^2 R^2 (Ai et al. 2011, eq. 15)
  tangential,        // k_r = k_t R^2 (LIGGGHTS epsd2, LAMMPS "rolling sds k_t")
};

template <class E>
struct ChoiceName {
  E value;
  const char* name;  // as written in the configuration
};

// Every value of each choice, in the enum's order (checked below), with its configuration name.
template <class E>
struct ChoiceTable;
template <>
struct ChoiceTable<NormalModel> {
  static constexpr const char* what = "normal model";
  static constexpr std::array<ChoiceName<NormalModel>, 2> values{{
      {NormalModel::linear, "linear"},
      {NormalModel::hertz, "hertz"},
  }};
};
template <>
struct ChoiceTable<TangentialModel> {
  static constexpr const char* what = "tangential model";
  static constexpr std::array<ChoiceName<TangentialModel>, 3> values{{
      {TangentialModel::coulomb, "coulomb"},
      {TangentialModel::blaze_viscous, "blaze_viscous"},
      {TangentialModel::blaze_tresca, "blaze_tresca"},
  }};
};
template <>
struct ChoiceTable<RollingModel> {
  static constexpr const char* what = "rolling model";
  static constexpr std::array<ChoiceName<RollingModel>, 4> values{{
      {RollingModel::none, "none"},
      {RollingModel::constant_torque, "constant_torque"},
      {RollingModel::elastic_plastic, "elastic_plastic"},
      {RollingModel::angular_damping, "angular_damping"},
  }};
};
template <>
struct ChoiceTable<DampingModel> {
  static constexpr const char* what = "damping model";
  static constexpr std::array<ChoiceName<DampingModel>, 2> values{{
      {DampingModel::restitution, "restitution"},
      {DampingModel::restitution_blaze, "restitution_blaze"},
  }};
};
template <>
struct ChoiceTable<RollingLeverArm> {
  static constexpr const char* what = "rolling lever arm";
  static constexpr std::array<ChoiceName<RollingLeverArm>, 2> values{{
      {RollingLeverArm::average_radius, "average_radius"},
      {RollingLeverArm::effective_radius, "effective_radius"},
  }};
};
template <>
struct ChoiceTable<RollingStiffness> {
  static constexpr const char* what = "rolling stiffness";
  static constexpr std::array<ChoiceName<RollingStiffness>, 2> values{{
      {RollingStiffness::ai2011, "ai2011"},
      {RollingStiffness::tangential, "tangential"},
  }};
};

// How many values a choice has.
template <class E>
inline constexpr std::size_t kChoiceCount = ChoiceTable<E>::values.size();

// The tables list the values in the enum's order, from 0: a value's index in its table is its
// integer value (the dispatch table relies on it).
template <class E>
constexpr bool listed_in_order() {
  for (std::size_t k = 0; k < kChoiceCount<E>; ++k)
    if (static_cast<std::size_t>(ChoiceTable<E>::values[k].value) != k) return false;
  return true;
}
static_assert(listed_in_order<NormalModel>() && listed_in_order<TangentialModel>() && listed_in_order<RollingModel>() &&
              listed_in_order<RollingLeverArm>() && listed_in_order<RollingStiffness>() &&
              listed_in_order<DampingModel>());

template <class E>
constexpr const char* to_string(E value) {
  for (const auto& c : ChoiceTable<E>::values)
    if (c.value == value) return c.name;
  return "?";
}

// The configuration names of a choice, in order ("linear", "hertz").
template <class E>
std::vector<std::string> choice_names() {
  std::vector<std::string> names;
  for (const auto& c : ChoiceTable<E>::values) names.emplace_back(c.name);
  return names;
}

// The value named `name`; throws InputError listing the names otherwise.
template <class E>
E parse_choice(std::string_view name);

// The choices of one contact law, as the compiler sees them: a law instance is compiled for each
// (a template argument of the batch loops), so that no branch on them is left in the loops. The
// damping model is not among them: it changes the dashpot's coefficient only (a parameter).
struct LawChoices {
  NormalModel normal = NormalModel::linear;
  TangentialModel tangential = TangentialModel::coulomb;
  RollingModel rolling = RollingModel::none;
  RollingLeverArm lever_arm = RollingLeverArm::average_radius;
  RollingStiffness rolling_stiffness = RollingStiffness::ai2011;
  bool rolling_dashpot = false;  // EPSD with eta_r > 0

  constexpr bool operator==(const LawChoices&) const = default;

  // The same law with the choices that do not apply reset (the lever arm, stiffness and dashpot
  // matter for the rolling models that read them only): one instance per distinct law.
  constexpr LawChoices canonical() const {
    LawChoices c = *this;
    if (c.rolling == RollingModel::none || c.rolling == RollingModel::angular_damping)
      c.lever_arm = RollingLeverArm::average_radius;
    if (c.rolling != RollingModel::elastic_plastic) {
      c.rolling_stiffness = RollingStiffness::ai2011;
      c.rolling_dashpot = false;
    }
    return c;
  }
};

// One axis of the law's choices: a member of LawChoices (an enum with its ChoiceTable, or a flag).
template <auto kMember>
struct LawAxis {
  using Value = std::remove_cvref_t<decltype(LawChoices{}.*kMember)>;
  static constexpr std::size_t count = [] {
    if constexpr (std::is_same_v<Value, bool>)
      return std::size_t{2};
    else
      return kChoiceCount<Value>;
  }();
  static constexpr std::size_t index(const LawChoices& c) { return static_cast<std::size_t>(c.*kMember); }
  static constexpr void set(LawChoices& c, std::size_t k) { c.*kMember = static_cast<Value>(k); }
};

// The law's axes, numbered as a mixed-radix number (the first axis the most significant digit):
// the dispatch table (law_dispatch.hpp) has one entry per number. A new axis is a member of
// LawChoices and an entry here.
template <class... Axes>
struct LawAxisList {
  static constexpr std::size_t kCount = (Axes::count * ... * std::size_t{1});
  static constexpr std::size_t number_of(const LawChoices& c) {
    std::size_t k = 0;
    ((k = k * Axes::count + Axes::index(c)), ...);
    return k;
  }
  static constexpr LawChoices numbered(std::size_t k) {
    constexpr std::array<std::size_t, sizeof...(Axes)> counts{Axes::count...};
    LawChoices c;
    std::size_t axis = 0;
    const auto digit = [&](std::size_t a) {
      std::size_t place = 1;
      for (std::size_t later = a + 1; later < counts.size(); ++later) place *= counts[later];
      return (k / place) % counts[a];
    };
    ((Axes::set(c, digit(axis)), ++axis), ...);
    return c;
  }
};
using LawAxes = LawAxisList<LawAxis<&LawChoices::normal>, LawAxis<&LawChoices::tangential>,
                            LawAxis<&LawChoices::rolling>, LawAxis<&LawChoices::lever_arm>,
                            LawAxis<&LawChoices::rolling_stiffness>, LawAxis<&LawChoices::rolling_dashpot>>;

}  // namespace trapdem
