#include "plot/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace trapdem::plot {

namespace {

// viridis (matplotlib, van der Walt & Smith) at 11 evenly spaced points; linear interpolation
// between them stays within a few per cent of the full table in lightness.
constexpr std::array<unsigned, 11> viridis_table{0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                                 0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};
// ColorBrewer RdBu (11 classes), ordered blue (low) to red (high), white in the middle.
constexpr std::array<unsigned, 11> diverging_table{0x053061, 0x2166ac, 0x4393c3, 0x92c5de, 0xd1e5f0, 0xf7f7f7,
                                                   0xfddbc7, 0xf4a582, 0xd6604d, 0xb2182b, 0x67001f};

template <std::size_t N>
Rgb interpolate(const std::array<unsigned, N>& table, double t) {
  const double s = std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(s), N - 2);
  const double f = s - static_cast<double>(i);
  const Rgb a = rgb_hex(table[i]), b = rgb_hex(table[i + 1]);
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace

Rgb rgb_hex(unsigned hex) {
  return {((hex >> 16) & 0xff) / 255.0, ((hex >> 8) & 0xff) / 255.0, (hex & 0xff) / 255.0};
}

Rgb ColourMap::at(double t) const {
  if (std::isnan(t)) return {0.85, 0.85, 0.85};
  return kind_ == ColourMapKind::viridis ? interpolate(viridis_table, t) : interpolate(diverging_table, t);
}

Rgb ColourMap::of(double value, double lo, double hi) const {
  if (!(hi > lo)) return at(0.5);
  return at((value - lo) / (hi - lo));
}

Rgb series_colour(std::size_t k) {
  static constexpr unsigned kOkabeIto[] = {0x0072B2, 0xD55E00, 0x009E73, 0xCC79A7, 0xE69F00, 0x56B4E9, 0x000000, 0xF0E442};
  return rgb_hex(kOkabeIto[k % 8]);
}

}  // namespace trapdem::plot
