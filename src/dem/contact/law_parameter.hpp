#pragma once
// A sub-model's parameter as the user gives it, declared once in the model's own file: its
// configuration key, the ContactLaw field it sets, its SI unit and its bounds. From these lists the
// configuration reader reads exactly the keys of the chosen models (and refuses a key no chosen
// model reads, naming the models that would), and ContactLaw::validate checks the same bounds:
// a model's rules are written in one place (contact_law.cpp: for_each_parameter, read_contact_law).
#include <limits>
#include <string_view>

namespace trapdem {

struct ContactLaw;

struct ParameterBounds {
  double lowest = -std::numeric_limits<double>::infinity();
  double highest = std::numeric_limits<double>::infinity();
  bool lowest_included = true;
  bool highest_included = true;

  constexpr bool contain(double v) const {  // false for NaN
    return (lowest_included ? v >= lowest : v > lowest) && (highest_included ? v <= highest : v < highest);
  }
};

struct LawParameter {
  std::string_view key;           // in a [contact] or [walls.*] table, and the ContactLaw field's name
  double ContactLaw::*field;
  std::string_view unit;          // SI ("" when dimensionless)
  ParameterBounds bounds;         // what the reader and validate accept
  std::string_view meaning;       // for messages: "a positive stiffness"
  // A default that follows another key of the same table when that one is given (k_t = k_n / 2 as
  // the seed's eq. 2, mu_k = mu_s): `follows` times `follow_factor`; else the base law's value.
  std::string_view follows = {};
  double follow_factor = 1.0;
  // A material property: read whatever the normal model, since another law's Hertz contact with
  // this body reads it (a wall's Hertz law combines its E and nu with the particles').
  bool material = false;
  // Refused in a table whose law no chosen model reads it with (its value would be ignored: a
  // stiffness under the Hertz law, Blaze-DEM's scales under trapdem's law). The friction keys are
  // not: a preset gives them for any law, and the seed-law studies switch the law over a preset.
  bool exclusive = false;
};

// Bounds: (lo, hi], [lo, hi], [lo, hi).
constexpr ParameterBounds open_closed(double lo, double hi) { return {lo, hi, false, true}; }
constexpr ParameterBounds closed(double lo, double hi) { return {lo, hi, true, true}; }
constexpr ParameterBounds closed_open(double lo, double hi) { return {lo, hi, true, false}; }

// The sanity bounds every model shares (a value past them is a typo, not a material).
inline constexpr double kMaxLawStiffness = 1e14;       // N/m: 2000x the paper's k_n = 4.5e10 N/m
inline constexpr double kMaxLawModulus = 1e13;         // Pa: diamond has E = 1.2e12 Pa
inline constexpr double kMaxLawFriction = 10.0;        // mu_s, mu_k, mu_r: measured ones are below 2
inline constexpr double kMaxRollingDamping = 10.0;     // eta_r: usual 0.3
inline constexpr double kMaxReferenceTimeStep = 1e-2;  // s: a DEM time step; Blaze-DEM's are ~1e-8 to 1e-6
inline constexpr double kMaxBlazeSpeed = 10.0;         // m/s: Blaze-DEM's u0 is 5e-4, its rest speed 0.01

}  // namespace trapdem
