#include "piv/subset_grid.hpp"

#include <string>

#include "core/errors.hpp"

namespace trapdem {

namespace {
std::string describe(const RegionOfInterest& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
         std::to_string(r.y1);
}
}  // namespace

SubsetGrid make_subset_grid(int image_width, int image_height, const std::optional<RegionOfInterest>& roi,
                            int subset_size, int step) {
  if (image_width <= 0 || image_height <= 0) throw InputError("PIV: the image is empty");
  if (subset_size < 5) throw InputError("PIV: subset size " + std::to_string(subset_size) + " px; must be >= 5");
  if (step < 1) throw InputError("PIV: subset step " + std::to_string(step) + " px; must be >= 1");
  if (subset_size > image_width || subset_size > image_height)
    throw InputError("PIV: subset size " + std::to_string(subset_size) + " px is larger than the image (" +
                     std::to_string(image_width) + " x " + std::to_string(image_height) + " px)");
  const RegionOfInterest r = roi.value_or(RegionOfInterest{0, 0, image_width, image_height});
  if (r.x1 <= r.x0 || r.y1 <= r.y0)
    throw InputError("PIV: the region of interest " + describe(r) + " (x0,y0,x1,y1 px) is empty");
  if (r.x0 < 0 || r.y0 < 0 || r.x1 > image_width || r.y1 > image_height)
    throw InputError("PIV: the region of interest " + describe(r) + " (x0,y0,x1,y1 px) is not inside the image (" +
                     std::to_string(image_width) + " x " + std::to_string(image_height) + " px)");
  if (r.width() < subset_size || r.height() < subset_size)
    throw InputError("PIV: no " + std::to_string(subset_size) + " px subset fits in the region of interest " +
                     describe(r) + " (x0,y0,x1,y1 px)");

  SubsetGrid g;
  g.subset_size = subset_size;
  g.step = step;
  g.columns = (r.width() - subset_size) / step + 1;
  g.rows = (r.height() - subset_size) / step + 1;
  const double half = -subset_first_offset(subset_size);
  g.centre.reserve(static_cast<std::size_t>(g.columns) * g.rows);
  for (int row = 0; row < g.rows; ++row)
    for (int col = 0; col < g.columns; ++col)
      g.centre.emplace_back(r.x0 + half + col * step, r.y0 + half + row * step);
  return g;
}

std::vector<std::size_t> grid_neighbours(const SubsetGrid& grid, std::size_t i) {
  const int col = grid.column_of(i), row = grid.row_of(i);
  std::vector<std::size_t> out;
  out.reserve(4);
  if (col > 0) out.push_back(grid.index(col - 1, row));
  if (col + 1 < grid.columns) out.push_back(grid.index(col + 1, row));
  if (row > 0) out.push_back(grid.index(col, row - 1));
  if (row + 1 < grid.rows) out.push_back(grid.index(col, row + 1));
  return out;
}

}  // namespace trapdem
