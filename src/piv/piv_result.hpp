#pragma once
// What a PIV run measures: for every subset of the grid on image 1 and every image, its total
// displacement from image 1 (px), the ZNCC of its match against the reference image in use,
// and a status that says whether it may be used.
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

#include "piv/subset_grid.hpp"
#include "piv/subset_warp.hpp"

namespace trapdem {

enum class SubsetStatus {
  valid,            // textured, converged, ZNCC >= min_valid_zncc
  low_texture,      // the reference subset fails the texture criteria: measured, never used
  low_correlation,  // converged with ZNCC below min_valid_zncc
  not_converged,    // IC-GN hit the iteration cap or diverged from every start
  left_image,       // the warped subset left the current image
  lost              // no reference subset: off the image after a reference update, or not
                    // tracked in the image that became the reference
};

std::string_view to_string(SubsetStatus status);

struct SubsetMeasurement {
  double u = std::numeric_limits<double>::quiet_NaN();  // px, total displacement from image 1, x right
  double v = std::numeric_limits<double>::quiet_NaN();  // px, y down
  double zncc = std::numeric_limits<double>::quiet_NaN();  // against the reference image in use
  WarpParameters relative;  // warp from the reference image in use (u, v and gradients)
  int iterations = 0;       // IC-GN iterations of the accepted solution
  double intensity_std = std::numeric_limits<double>::quiet_NaN();         // reference subset, grey levels
  double sum_squared_gradient = std::numeric_limits<double>::quiet_NaN();  // reference subset SSSIG
  SubsetStatus status = SubsetStatus::lost;

  bool is_valid() const { return status == SubsetStatus::valid; }
};

struct ImageMeasurements {
  std::size_t reference = 0;  // index of the reference image the match was made against
  std::vector<SubsetMeasurement> subset;  // one per grid subset
  double seconds = 0.0;       // wall time for this image: load, interpolation, matching (all attempts)
  int attempts = 1;           // 2 if the reference was updated for this image
};

struct PivResult {
  SubsetGrid grid;                          // subset centres in image 1
  std::vector<ImageMeasurements> image;     // image[0] is image 1 itself (zero displacement)
  std::vector<std::size_t> reference_images;  // the references used, in order (starts with 0)

  std::size_t image_count() const { return image.size(); }
};

// Number of valid subsets in image k.
std::size_t count_valid(const PivResult& result, std::size_t k);

}  // namespace trapdem
