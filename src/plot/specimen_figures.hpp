#pragma once
// The figures of one analysed run (like the seed paper's Figures 5 and 7), drawn from an
// AnalysisResult with lengths on the axes in mm:
//  - the maximum shear strain map over the box (constant-strain triangles on the reference
//    centres), colour bar, trapdoor, traced band centres, title with case and displacement;
//  - vertical displacement: settlement contours with labels over a diverging colour fill;
//  - particles at their current positions, radius to scale, coloured by vertical displacement;
//  - a panel of several runs' strain maps side by side with one shared colour scale (Figure 7).
#include <filesystem>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "plot/axes.hpp"

namespace trapdem::plot {

enum class StrainKind { total, incremental };

// The upper end of the colour scale: the 95th percentile of gamma_max rounded up to 1, 2, 2.5 or
// 5 x 10^k (values above saturate; the colour bar marks it).
double auto_strain_scale(const AnalysisResult& result, StrainKind kind = StrainKind::total);

// Draws the strain map with axes into `area` (pixels, axes labels inside it); no title, no bar.
// Returns the frame used.
PlotFrame draw_strain_map(cairo_t* cr, Rect area, const AnalysisResult& result, StrainKind kind, double vmax,
                          double font_size = 16.0);

// Figure sizes: width given, height follows the box's aspect.
void write_strain_map_png(const std::filesystem::path& path, const AnalysisResult& result, StrainKind kind,
                          double vmax = 0.0, int width = 1200);
void write_displacement_contours_png(const std::filesystem::path& path, const AnalysisResult& result,
                                     int width = 1200);
void write_particles_png(const std::filesystem::path& path, const AnalysisResult& result, int width = 1200);
// vmax = 0: the largest of the runs' auto scales.
void write_strain_panel_png(const std::filesystem::path& path, const std::vector<const AnalysisResult*>& results,
                            double vmax = 0.0, int panel_width = 560);

}  // namespace trapdem::plot
