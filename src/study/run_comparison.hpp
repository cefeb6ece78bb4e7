#pragma once
// A DEM run folder against a PIV measurement (`trapdem compare`, and each case of a calibration):
// the DEM and PIV vertical displacement fields on one grid (model coordinates, trapdoor centre as
// origin), one error number (RMS of w_DEM - w_PIV over the common area over the trapdoor
// displacement) with the bias and coverage, and the overlay figure of both settlement contour sets
// (issue 6; docs/analysis.md).
#include <cstddef>
#include <filesystem>
#include <string>

#include "analysis/analysis_run.hpp"
#include "analysis/dem_piv_comparison.hpp"

namespace trapdem {

struct CompareOptions {
  std::string dem_dir;          // run folder: resolved.toml, snapshots.h5
  std::string piv_dir;          // folder with piv.h5 (or the file itself)
  std::string at;               // trapdoor displacement, e.g. "10mm" (required)
  std::string grid = "2mm";     // spacing of the common grid
  std::size_t image = 0;        // PIV image (1-based); 0: matched to the DEM snapshot by name
  std::size_t reference_image = 0;  // PIV image of the reference (start of lowering); 0: matched, else 1
  std::string piv_trapdoor;     // "X,Z" lengths: the trapdoor centre in the PIV model coordinates;
                                // empty: the DEM box coordinates (as `trapdem render` gives)
  std::string out;              // figure; empty: DEM_DIR/analysis/compare_<at>mm.png
  bool no_figure = false;
  bool json = false;            // JSON on stdout instead of the text
};

struct CompareResult {
  SpecimenGeometry geometry;
  double reference_displacement = 0.0, at_displacement = 0.0;  // m, of the DEM snapshots used
  std::string dem_reference_label, dem_at_label;               // snapshot group names
  std::size_t piv_reference_image = 0, piv_image = 0;         // 1-based
  std::string piv_reference_name, piv_image_name;
  std::string image_choice;     // how the PIV images were chosen, for the report
  GridField dem, piv;           // on the common grid, m (NaN outside each field)
  FieldComparison error;
  double trapdoor_travel() const { return at_displacement - reference_displacement; }
};

// Reads, matches and compares (no output written). Throws InputError / FileError.
CompareResult compare_directories(const CompareOptions& options);

// The overlay figure of both settlement contour sets, with the error in its subtitle.
void write_compare_figure(CompareResult result, const std::filesystem::path& png);

// The default figure: DEM_DIR/analysis/compare_<at>mm.png.
std::filesystem::path default_compare_figure(const CompareOptions& options, const CompareResult& result);

// "12.34 %" for a fraction.
std::string percent_text(double fraction);

}  // namespace trapdem
