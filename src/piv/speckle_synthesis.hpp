#pragma once
// Synthetic speckle images under a prescribed displacement field, for tests and for users to
// check their settings. The pattern is a sum of Gaussian speckles (the usual model of synthetic
// DIC images), with a smooth saturation:
//   S(X) = sum_k exp(-|X - X_k|^2 / (2 s_k^2)),   I = background + (foreground - background)(1 - exp(-S)).
// A deformed image is I(X(x)): every speckle is drawn at its displaced centre x_k = X_k + u(X_k)
// and shaped by the local deformation gradient F = I + grad u (exact for uniform gradients, first
// order otherwise): exp(-(x - x_k)^T (F F^T)^-1 (x - x_k) / (2 s_k^2)). Point sampling, then
// optional Gaussian noise, then rounding to the bit depth. All random numbers come from the
// seed: the same settings give the same images.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "piv/displacement_fields.hpp"

namespace trapdem {

struct SpeckleSettings {
  int width = 256;               // px
  int height = 256;              // px
  double speckle_radius = 2.0;   // px, mean standard deviation s of a speckle (sizes vary +-25 %)
  double coverage = 0.6;         // speckle count per area: coverage / (pi s^2)
  double margin = 48.0;          // px, the pattern extends this far beyond the image on every side
  double background = 30.0;      // grey levels (8-bit scale)
  double foreground = 230.0;     // grey levels
  double noise_std = 0.0;        // grey levels, additive Gaussian noise of every image
  int bit_depth = 8;             // 8 (CV_8U) or 16 (CV_16U; grey levels times 257)
  std::uint64_t seed = 1;
};

struct Speckle {
  cv::Point2d centre;  // px, reference position
  double radius = 0.0; // px, standard deviation
};

// The speckles of the reference pattern. Throws InputError for a non-positive size or radius.
std::vector<Speckle> make_speckle_pattern(const SpeckleSettings& settings);

// The pattern deformed by `field`, with noise drawn from `noise_seed`.
cv::Mat render_speckle_image(const std::vector<Speckle>& pattern, const DisplacementField& field,
                             const SpeckleSettings& settings, std::uint64_t noise_seed);

// Image 1 undeformed, then one image per field (each field is the total displacement from
// image 1). Image k's noise uses seed settings.seed + k.
std::vector<cv::Mat> synthesize_speckle_sequence(const SpeckleSettings& settings,
                                                 const std::vector<DisplacementField>& fields);

}  // namespace trapdem
