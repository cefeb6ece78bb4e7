#pragma once
// The control point file of `trapdem piv --control-points FILE` (docs/piv.md): one point a line,
// "x_px, y_px, x_model, z_model"; blank lines, '#' comments and header lines (not starting with a
// digit, '-' or '.') skipped.
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "piv/pixel_to_model.hpp"

namespace trapdem {

// Throws InputError "<name>:<line>: ..." for a line that is not four finite numbers.
std::vector<ControlPoint> parse_control_points(std::istream& in, const std::string& name);
// The same from a file; InputError if it cannot be opened.
std::vector<ControlPoint> read_control_points(const std::filesystem::path& file);

}  // namespace trapdem
