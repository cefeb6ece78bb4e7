// The contact law's parameters as the sub-models declare them (contact/law_parameter.hpp): the
// lists are consistent, ContactLaw::validate is generated from them (a chosen model's parameter out
// of its bounds is refused naming the key, another model's is not its business), and the messages
// name the choices that read a key.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/errors.hpp"
#include "dem/contact/damping.hpp"
#include "dem/contact/models.hpp"
#include "dem/contact_law.hpp"

using namespace trapdem;

namespace {

// A law under which the key is read by a model that is on.
ContactLaw law_reading(std::string_view key) {
  ContactLaw law;
  law.rolling_friction = 0.1;
  law.rolling_model = RollingModel::elastic_plastic;
  law.youngs_modulus = 5e7;
  if (key == "youngs_modulus" || key == "poisson_ratio") law.normal_model = NormalModel::hertz;
  if (key == "reference_time_step" || key == "blaze_velocity_scale" || key == "blaze_rest_speed") {
    law.tangential_model = TangentialModel::blaze_viscous;
    law.reference_time_step = 1e-7;
  }
  return law;
}

// A value just past the bounds (above the upper one, or below the lower one when it is open at
// infinity above).
double past(const ParameterBounds& b) {
  if (std::isfinite(b.highest)) return b.highest_included ? std::nextafter(b.highest, 2 * b.highest + 1) : b.highest;
  return b.lowest_included ? std::nextafter(b.lowest, -std::numeric_limits<double>::infinity()) : b.lowest;
}

}  // namespace

TEST(LawParameters, EachKeyIsDeclaredOnceWithItsWidestBoundsFirst) {
  const std::vector<LawParameter> declared = declared_parameters();
  std::set<std::string_view> keys;
  for (const LawParameter& p : declared) EXPECT_TRUE(keys.insert(p.key).second) << p.key << " twice";
  EXPECT_EQ(declared.front().key, "rolling_friction");  // read first: whether a rolling model is on
  // Every model's declaration of a key lies within the first one (the reader reads within it and
  // checks the chosen model's narrower bounds as a rule), and names the same field.
  auto check = [&](const LawParameter& p) {
    const LawParameter* first = nullptr;
    for (const LawParameter& q : declared)
      if (q.key == p.key) first = &q;
    ASSERT_NE(first, nullptr) << p.key << " not in declared_parameters()";
    EXPECT_EQ(first->field, p.field) << p.key;
    EXPECT_LE(first->bounds.lowest, p.bounds.lowest) << p.key;
    EXPECT_GE(first->bounds.highest, p.bounds.highest) << p.key;
  };
  auto check_model = [&](auto model) {
    for (const LawParameter& p : decltype(model)::parameters) check(p);
  };
  NormalModels::for_each(check_model);
  TangentialModels::for_each(check_model);
  RollingModels::for_each(check_model);
  for (const LawParameter& p : RestitutionDamping::parameters) check(p);
  // A key that follows another follows a declared one.
  for (const LawParameter& p : declared)
    if (!p.follows.empty()) {
      EXPECT_TRUE(keys.count(p.follows)) << p.key << " follows " << p.follows;
    }
}

TEST(LawParameters, ValidateRefusesAChosenModelsParameterPastItsBounds) {
  for (const LawParameter& p : declared_parameters()) {
    ContactLaw law = law_reading(p.key);
    ASSERT_NO_THROW(law.validate("contact")) << p.key;
    const double bad = past(p.bounds);
    law.*p.field = bad;
    if (p.key == "rolling_friction") law.rolling_model = RollingModel::angular_damping, law.reference_time_step = 1e-7;
    try {
      law.validate("contact");
      ADD_FAILURE() << p.key << " = " << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("contact." + std::string(p.key)), std::string::npos) << e.what();
    }
  }
  // A model not chosen reads nothing: the linear stiffness under the Hertz law is not checked, nor
  // Blaze-DEM's time step under trapdem's law, nor the rolling damping when rolling is off.
  ContactLaw hertz = law_reading("youngs_modulus");
  hertz.normal_stiffness = -1.0;
  hertz.reference_time_step = 0.0;
  EXPECT_NO_THROW(hertz.validate("contact"));
  ContactLaw off;
  off.rolling_model = RollingModel::elastic_plastic;
  off.rolling_friction = 0.0;
  off.rolling_damping = -1.0;
  EXPECT_NO_THROW(off.validate("contact"));
  off.rolling_friction = 0.1;
  EXPECT_THROW(off.validate("contact"), InputError);
}

TEST(LawParameters, MessagesNameTheChoicesThatReadAKey) {
  EXPECT_EQ(readers_of("normal_stiffness"), "normal_model = \"linear\"");
  EXPECT_EQ(readers_of("youngs_modulus"), "normal_model = \"hertz\"");
  EXPECT_EQ(readers_of("reference_time_step"),
            "tangential_model = \"blaze_viscous\" or \"blaze_tresca\", or rolling_model = \"angular_damping\" with "
            "rolling_friction > 0");
  EXPECT_EQ(readers_of("rolling_friction"),
            "rolling_model = \"constant_torque\" or \"elastic_plastic\" or \"angular_damping\"");
  EXPECT_EQ(readers_of("restitution"), "every law");
}
