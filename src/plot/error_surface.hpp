#pragma once
// The calibration's error surface: the error of each case of a parameter grid. Two varied keys: a
// heat map of cells (one per value pair, the error written in each, the best outlined); one key: the
// error against its value. `trapdem calibrate` draws it.
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem::plot {

struct ErrorSurface {
  std::string title, subtitle;
  std::string error_label;              // "RMS(w_DEM - w_PIV) / δ (%)"
  std::string x_key, y_key;             // y_key empty: one key
  std::vector<std::string> x_values, y_values;  // tick labels, in grid order
  std::vector<double> error;            // error[iy * x_values.size() + ix]; NaN: not scored
  double error_scale = 1.0;             // shown value = error * error_scale (100 for %)
};

// Throws std::invalid_argument if error.size() does not match the grid.
void write_error_surface(const std::filesystem::path& path, const ErrorSurface& surface);

}  // namespace trapdem::plot
