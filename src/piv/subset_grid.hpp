#pragma once
// Square subsets on a regular grid inside a region of interest of the first image. Pixel (col,
// row) has its centre at (x, y) = (col, row), x right and y down, in px. A subset of side L
// covers the L x L pixels whose centres lie within (L - 1) / 2 of its centre, so an even L puts the
// centre between pixels; in the first image every subset pixel is a whole pixel.
#include <cstddef>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

namespace trapdem {

// Half-open pixel rectangle [x0, x1) x [y0, y1), px.
struct RegionOfInterest {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;

  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

struct SubsetGrid {
  int subset_size = 0;  // px, L
  int step = 0;         // px between neighbouring centres
  int columns = 0;      // subsets along x
  int rows = 0;         // subsets along y
  std::vector<cv::Point2d> centre;  // px, in the first image; index row * columns + column

  std::size_t size() const { return centre.size(); }
  std::size_t index(int column, int row) const { return static_cast<std::size_t>(row) * columns + column; }
  int column_of(std::size_t i) const { return static_cast<int>(i % static_cast<std::size_t>(columns)); }
  int row_of(std::size_t i) const { return static_cast<int>(i / static_cast<std::size_t>(columns)); }
};

// Offset of the first subset pixel from the subset centre: -(L - 1) / 2, px.
inline double subset_first_offset(int subset_size) { return -0.5 * (subset_size - 1); }

// The subsets of side subset_size every `step` px whose pixels all lie in `roi` (the whole
// image if not given), starting at the ROI's top-left corner. Throws InputError if the image is
// empty, the subset is larger than the image, the subset size or step is below 1 (subset below
// 5), the ROI is empty or not inside the image, or no subset fits in the ROI.
SubsetGrid make_subset_grid(int image_width, int image_height, const std::optional<RegionOfInterest>& roi,
                            int subset_size, int step);

// Indices of the (up to four) edge neighbours of subset i: left, right, up, down.
std::vector<std::size_t> grid_neighbours(const SubsetGrid& grid, std::size_t i);

}  // namespace trapdem
