#pragma once
// PIV over an image sequence as GeoPIV-RG does it (Stanier et al. 2016): subsets on a grid of
// image 1, each image matched against a reference image (image_pair.hpp), and the reference
// updated ("leapfrog") to the image before the current one when a textured subset's ZNCC falls
// below reference_update_zncc; the subsets of the new reference sit at their displaced positions,
// so their total displacement from image 1 is the reference's total plus the new match.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "piv/grey_image.hpp"
#include "piv/piv_result.hpp"
#include "piv/piv_settings.hpp"

namespace trapdem {

// Called after each image is done (index from 0; image 0 is the first reference).
using PivProgress = std::function<void(std::size_t image, const ImageMeasurements& measured)>;

// The general form: `load(k)` gives image k of `count` (loaded one at a time, at most three held),
// `name(k)` names it in error messages. Throws InputError for fewer than two images, images of
// different sizes, and the grid errors of make_subset_grid (empty ROI, subset larger than the image).
PivResult run_piv(std::size_t count, const std::function<GreyImage(std::size_t)>& load,
                  const std::function<std::string(std::size_t)>& name, const PivSettings& settings,
                  const PivProgress& progress = {});

// Images in memory (8/16-bit, grey or colour; see to_grey_image).
PivResult run_piv(const std::vector<cv::Mat>& images, const PivSettings& settings, const PivProgress& progress = {});

// Image files in order; every file is checked to be a readable image before the run starts.
PivResult run_piv(const std::vector<std::filesystem::path>& files, const PivSettings& settings,
                  const PivProgress& progress = {});

}  // namespace trapdem
