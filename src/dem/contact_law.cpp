#include "dem/contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dem/contact/law.hpp"
#include "core/errors.hpp"

namespace trapdem {

double ContactLaw::damping_restitution() const {
  // Blaze-DEM V_02_2015, src/Input/KSimulationData.cpp (every Set_SpringConstants* function):
  // `if (COR >= 0.30 && COR <= 0.90) COR -= 0.038080;` before c_n is computed from it.
  if (damping_model == DampingModel::restitution_blaze && restitution >= 0.3 && restitution <= 0.9)
    return restitution - 0.03808;
  return restitution;
}

double ContactLaw::damping_ratio() const {
  const double e = damping_restitution();
  if (e >= 1.0) return 0.0;
  const double log_e = std::log(e);
  return -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

namespace {

// What a parameter's bounds accept, in words: "a positive stiffness in (0, 1e+14] N/m".
std::string expected(const LawParameter& p) {
  return fmt::format("{} in {}{:g}, {:g}{}{}", p.meaning, p.bounds.lowest_included ? "[" : "(", p.bounds.lowest,
                     p.bounds.highest, p.bounds.highest_included ? "]" : ")", p.unit.empty() ? "" : " ", p.unit);
}

[[noreturn]] void fail(const std::string& where, const LawParameter& p, double value) {
  throw InputError(fmt::format("{}.{} = {}: expected {}", where, p.key, value, expected(p)));
}

template <class List, class Choice>
void append_model_parameters(Choice chosen, std::vector<LawParameter>& out) {
  List::visit(chosen, [&](auto model) {
    for (const LawParameter& p : decltype(model)::parameters) out.push_back(p);
    return 0;
  });
}

}  // namespace

namespace {
// The parameters of the law's normal, damping and tangential models, and of its rolling model when
// `with_rolling`.
std::vector<LawParameter> parameters_of(const ContactLaw& law, bool with_rolling) {
  std::vector<LawParameter> out;
  append_model_parameters<NormalModels>(law.normal_model, out);
  for (const LawParameter& p : RestitutionDamping::parameters) out.push_back(p);
  append_model_parameters<TangentialModels>(law.tangential_model, out);
  if (with_rolling) append_model_parameters<RollingModels>(law.rolling_model, out);
  return out;
}
}  // namespace

std::vector<LawParameter> chosen_parameters(const ContactLaw& law) { return parameters_of(law, true); }

// A rolling model with mu_r = 0 is off (law_choices): none of its parameters is read then.
std::vector<LawParameter> active_parameters(const ContactLaw& law) { return parameters_of(law, law.rolling_friction != 0.0); }

std::vector<LawParameter> declared_parameters() {
  std::vector<LawParameter> out;
  auto add = [&](const LawParameter& p) {
    for (const LawParameter& q : out)
      if (q.key == p.key) return;
    out.push_back(p);
  };
  auto add_model = [&](auto model) {
    for (const LawParameter& p : decltype(model)::parameters) add(p);
  };
  add(ConstantTorqueRolling::parameters[0]);  // rolling_friction first: whether rolling is on depends on it
  NormalModels::for_each(add_model);
  for (const LawParameter& p : RestitutionDamping::parameters) add(p);
  TangentialModels::for_each(add_model);
  RollingModels::for_each(add_model);
  return out;
}

std::string readers_of(std::string_view key) {
  std::vector<std::string> readers;
  auto of_axis = [&](auto list, const char* axis) {
    std::vector<std::string> names;
    decltype(list)::for_each([&](auto model) {
      using Model = decltype(model);
      for (const LawParameter& p : Model::parameters)
        if (p.key == key) names.push_back(fmt::format("\"{}\"", to_string(Model::model)));
    });
    if (names.empty()) return;
    std::string text = fmt::format("{} = ", axis);
    for (std::size_t k = 0; k < names.size(); ++k) text += (k == 0 ? "" : " or ") + names[k];
    if (std::string_view(axis) == "rolling_model" && key != "rolling_friction") text += " with rolling_friction > 0";
    readers.push_back(std::move(text));
  };
  of_axis(NormalModels{}, "normal_model");
  of_axis(TangentialModels{}, "tangential_model");
  of_axis(RollingModels{}, "rolling_model");
  std::string text;
  for (std::size_t k = 0; k < readers.size(); ++k) text += (k == 0 ? "" : ", or ") + readers[k];
  return text.empty() ? "every law" : text;
}

void ContactLaw::validate(const std::string& where) const {
  for (const LawParameter& p : active_parameters(*this))
    if (!p.bounds.contain(this->*p.field)) fail(where, p, this->*p.field);
}

void ContactLaw::validate_material(const std::string& where) const {
  for (const LawParameter& p : NormalHertz::parameters)
    if (!p.bounds.contain(this->*p.field)) fail(where, p, this->*p.field);
}

template <class E>
E parse_choice(std::string_view name) {
  std::string names;
  for (const auto& c : ChoiceTable<E>::values) {
    if (name == c.name) return c.value;
    names += names.empty() ? c.name : fmt::format(", {}", c.name);
  }
  throw InputError(fmt::format("{} '{}': expected one of {}", ChoiceTable<E>::what, name, names));
}
template NormalModel parse_choice<NormalModel>(std::string_view);
template TangentialModel parse_choice<TangentialModel>(std::string_view);
template DampingModel parse_choice<DampingModel>(std::string_view);
template RollingModel parse_choice<RollingModel>(std::string_view);
template RollingLeverArm parse_choice<RollingLeverArm>(std::string_view);
template RollingStiffness parse_choice<RollingStiffness>(std::string_view);

LawChoices law_choices(const ContactLaw& law) {
  LawChoices c;
  c.normal = law.normal_model;
  c.tangential = law.tangential_model;
  c.rolling = law.rolling_friction > 0.0 ? law.rolling_model : RollingModel::none;
  c.lever_arm = law.lever_arm;
  c.rolling_stiffness = law.rolling_stiffness;
  c.rolling_dashpot = c.rolling == RollingModel::elastic_plastic && law.rolling_damping > 0.0;
  return c.canonical();
}

LawParams law_params(const ContactLaw& law, const ContactLaw& particle_law) {
  LawParams p;
  const double damping_scale = NormalModels::visit(law.normal_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.normal) = Model::params(law, particle_law);
    return Model::damping_scale;
  });
  p.damping.factor = 2.0 * damping_scale * law.damping_ratio();
  TangentialModels::visit(law.tangential_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.tangential) = Model::params(law);
    return 0;
  });
  p.mu_r = law.rolling_friction;
  RollingModels::visit(law.rolling_model, [&](auto model) {
    using Model = decltype(model);
    static_cast<typename Model::Params&>(p.rolling) = Model::params(law);
    return 0;
  });
  return p;
}

double spin_retention(const ContactLaw& law, double dt) {
  if (!damps_spin(law_choices(law))) return 1.0;
  return RollingModels::visit(law.rolling_model, [&](auto model) {
    using Model = decltype(model);
    if constexpr (Model::damps_spin)
      return Model::spin_retention(law, dt);
    else
      return 1.0;
  });
}

double contact_time_scale(const ContactLaw& law, const ContactLaw& particle_law, double mass, double radius) {
  return NormalModels::visit(law.normal_model, [&](auto model) {
    return decltype(model)::time_scale(law, particle_law, mass, radius);
  });
}

double critical_time_step(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws, double mass,
                          double radius) {
  double t = contact_time_scale(particle_law, particle_law, mass, radius);
  for (const ContactLaw* law : wall_laws) t = std::min(t, contact_time_scale(*law, particle_law, mass, radius));
  return t;
}

std::string critical_time_step_formula(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws) {
  std::vector<std::string_view> formulas;  // each normal model's once, in the list's order
  NormalModels::for_each([&](auto model) {
    using Model = decltype(model);
    bool used = particle_law.normal_model == Model::model;
    for (const ContactLaw* law : wall_laws) used = used || law->normal_model == Model::model;
    if (used) formulas.push_back(Model::time_scale_formula);
  });
  if (formulas.size() == 1) return std::string(formulas.front());
  std::string text = "min(";
  for (std::size_t k = 0; k < formulas.size(); ++k) text += fmt::format("{}{}", k == 0 ? "" : ", ", formulas[k]);
  return text + ")";
}

bool combines_materials(const ContactLaw& law) {
  return NormalModels::visit(law.normal_model, [](auto model) { return decltype(model)::combines_materials; });
}

const LawParameter& stiffness_parameter(const ContactLaw& law) {
  return *NormalModels::visit(law.normal_model, [](auto model) {
    using Model = decltype(model);
    return &Model::parameters[Model::stiffness_parameter];
  });
}

std::string describe_law(const ContactLaw& law) {
  const LawChoices c = law_choices(law);
  std::string text = fmt::format("{} normal, {} damping, {} tangential, {} rolling", to_string(c.normal),
                                 to_string(law.damping_model), to_string(c.tangential), to_string(c.rolling));
  std::vector<std::string_view> said;
  for (const LawParameter& p : active_parameters(law)) {
    if (std::find(said.begin(), said.end(), p.key) != said.end()) continue;
    said.push_back(p.key);
    text += fmt::format("{}{} = {:.4g}{}{}", said.size() == 1 ? ": " : ", ", p.key, law.*p.field,
                        p.unit.empty() ? "" : " ", p.unit);
  }
  return text;
}

std::string describe_stiffness(const ContactLaw& law, const std::string& owner) {
  const LawParameter& p = stiffness_parameter(law);
  const std::string_view name =
      NormalModels::visit(law.normal_model, [](auto model) { return decltype(model)::stiffness_name; });
  return fmt::format("{} of the {} contact law ({:.4g} {})", name, owner, law.*p.field, p.unit);
}

}  // namespace trapdem
