#pragma once
// Colour maps for the figures: a perceptually uniform sequential map (viridis, for magnitudes
// such as the maximum shear strain) and a diverging map (blue - white - red, for signed fields
// such as the vertical displacement, white at zero).
#include <cstddef>
#include <string>

namespace trapdem::plot {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  // each in [0, 1]
};

enum class ColourMapKind { viridis, diverging };

class ColourMap {
 public:
  explicit ColourMap(ColourMapKind kind) : kind_(kind) {}
  // The colour at t in [0, 1] (clamped; NaN gives light grey).
  Rgb at(double t) const;
  // The colour of `value` on the scale [lo, hi].
  Rgb of(double value, double lo, double hi) const;
  ColourMapKind kind() const { return kind_; }

 private:
  ColourMapKind kind_;
};

// 0xRRGGBB as a colour.
Rgb rgb_hex(unsigned hex);

// The k-th colour for one of several series (cases on one chart): Okabe & Ito's palette, told apart
// by colour-blind readers too; it repeats after eight.
Rgb series_colour(std::size_t k);

}  // namespace trapdem::plot
