#pragma once
// The figures of one analysed run (like the seed paper's Figures 5 and 7), drawn from an
// AnalysisResult with lengths on the axes in mm, each written in the format its path's extension
// names (PNG, SVG or PDF: canvas.hpp) and legible one journal column wide (text.hpp):
//  - the maximum shear strain map over the box (constant-strain triangles on the reference
//    centres), colour bar, trapdoor, traced band centres;
//  - the volumetric strain (dilation) map beside it: the same triangles on a diverging scale
//    centred on 0, compression positive as the metrics state it;
//  - settlement (downward displacement) contours with labels over a diverging colour fill, the
//    colour bar in the same sign convention as the labels;
//  - particles at their current positions, radius to scale, coloured by settlement;
//  - a panel of several runs' strain maps on one colour scale and one length scale (Figure 7),
//    a run whose snapshots are gone drawn from its stored grid (StoredStrainMap).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "analysis/grid_field.hpp"
#include "analysis/shear_bands.hpp"
#include "analysis/trapdoor_geometry.hpp"
#include "plot/axes.hpp"
#include "plot/contour_plot.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

enum class StrainKind { total, incremental };

// The upper end of the colour scale: the 95th percentile of gamma_max rounded up to 1, 2, 2.5 or
// 5 x 10^k (values above saturate; the colour bar marks it).
double auto_strain_scale(const AnalysisResult& result, StrainKind kind = StrainKind::total);

// The volumetric strain the map shows: the total volumetric strain per triangle, compression
// positive, smoothed as the shear strain map is (at the analysis's smoothing length).
std::vector<double> shown_volumetric_strain(const AnalysisResult& result);

// Draws the strain map with axes into `area` (layout units, axes labels inside it); no title, no
// bar. Returns the frame used.
PlotFrame draw_strain_map(cairo_t* cr, Rect area, const AnalysisResult& result, StrainKind kind, double vmax,
                          double font_size = kFontSmall);

// Each writes one figure `width` layout units wide (the height follows the box's aspect) and
// returns the map's frame in layout units (a PNG has kPngPixelsPerUnit pixels per unit).
PlotFrame write_strain_map(const std::filesystem::path& path, const AnalysisResult& result, StrainKind kind,
                           double vmax = 0.0, int width = static_cast<int>(kFigureWidth));
// vmax = 0: the 95th percentile of |volumetric strain| rounded up (nice_ceiling); the scale is
// -vmax..vmax, white at 0.
PlotFrame write_volumetric_strain_map(const std::filesystem::path& path, const AnalysisResult& result,
                                      double vmax = 0.0, int width = static_cast<int>(kFigureWidth));
// Levels in metres of settlement (downward positive); default: automatic 1-2-5 levels.
PlotFrame write_displacement_contours(const std::filesystem::path& path, const AnalysisResult& result,
                                      const ContourLevels& levels = {}, int width = static_cast<int>(kFigureWidth));
PlotFrame write_particles_figure(const std::filesystem::path& path, const AnalysisResult& result,
                                 int width = static_cast<int>(kFigureWidth));

// A run's total gamma_max at its last snapshot on a regular grid, for a run whose snapshots are
// gone: field_history.h5's last layer (the constant-strain triangles sampled at one mean diameter)
// smoothed as its analysis smoothed the triangles, with the geometry and the band traces of its
// metrics.json (study/stored_analysis.hpp reads them). Coarser than the triangles (one value per
// diameter), the same field.
struct StoredStrainMap {
  std::string name;
  GridField gamma_max;               // -, NaN in empty space (inside the specimen filled: fill_interior_grid_holes)
  double box_width = 0.0;            // m
  TrapdoorGeometry trapdoor;         // centre and width (m); the base at z = 0
  double travel = 0.0;               // m, the trapdoor's displacement at the layer
  double mean_diameter = 0.0;        // m
  double smoothing_diameters = 0.0;  // the Gaussian's L in mean diameters (0: unsmoothed)
  std::vector<std::vector<BandTracePoint>> band_traces, branch_traces;  // metrics.json's shear_bands
};

// The colour scale's upper end for a stored map: its grid's 95th percentile, rounded up as
// auto_strain_scale rounds (the grid weights each triangle by its area, the analysis's scale each
// triangle once: a little apart on the same field).
double auto_strain_scale(const StoredStrainMap& map);

// One panel of a strain panel: a run's analysis, or its stored map where the snapshots are gone.
struct StrainPanelMap {
  const AnalysisResult* analysis = nullptr;
  const StoredStrainMap* stored = nullptr;
};

// Several runs' total strain maps, one colour scale (vmax = 0: the largest of the runs' auto
// scales) and one length scale: every panel has the same mm per unit and the same vertical range,
// so the boxes, bases and trapdoors line up. One column of panels for up to four runs (for one
// journal column, 85 mm), two columns beyond (for a page width). A stored map is drawn as its
// grid's cells and says so under its label ("stored grid").
// Panel titles: `labels[k]` (a study's case labels), else each run's name. Returns the frames.
std::vector<PlotFrame> write_strain_panel_of_maps(const std::filesystem::path& path,
                                                  const std::vector<StrainPanelMap>& maps,
                                                  const std::vector<std::string>& labels = {}, double vmax = 0.0);
std::vector<PlotFrame> write_strain_panel(const std::filesystem::path& path,
                                          const std::vector<const AnalysisResult*>& results,
                                          const std::vector<std::string>& labels = {}, double vmax = 0.0);

}  // namespace trapdem::plot
