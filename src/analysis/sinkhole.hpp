#pragma once
// How large can the sinkhole get? Two estimates of the maximum surface diameter of a sinkhole.
//
// 1. Scenario supposition (Buttrick & Van Schalkwyk 1995, J. SAICE 37(4): 9-14, the method SANS 1936
//    recommends; the seed paper's Figure 1): a cone of draw rises from the cavity throat through each
//    blanket layer, widening by t_i tan(alpha_i) on each side, so
//        D_s = D_throat + 2 sum_i t_i tan(alpha_i)
//    with layer thickness t_i and angle of draw alpha_i measured from the vertical. The construction
//    follows the seed's description of Figure 1 and shared/reference/formulas.md; the original paper
//    could not be read (see docs/sinkhole.md).
// 2. Mechanism-based, from a DEM trapdoor run: the zone of influence at the surface (analysis/metrics.json)
//    scaled to prototype by the run's g level (centrifuge similitude: lengths x N), beside the supposition
//    estimate for the same geometry and the angle of draw the DEM implies.
//
// Plain functions; lengths in metres, angles in degrees. Bad input throws InputError. Reading a run
// folder: study/sinkhole_run.hpp; the JSON form: analysis/sinkhole_json.hpp.
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// SANS 1936 size classes of the surface diameter (check: as quoted in shared/reference/formulas.md).
// Boundaries: small D < 2 m; medium 2 <= D < 5 m; large 5 <= D <= 15 m; very large D > 15 m. The
// written "< 2 m" and "> 15 m" are strict, so 2 m is medium and 15 m is large; 5 m, which both
// "2-5 m" and "5-15 m" name, goes to the larger class (the conservative side, as at 2 m).
enum class SinkholeSizeClass { small, medium, large, very_large };

SinkholeSizeClass classify_sinkhole(double surface_diameter_m);
const char* size_class_name(SinkholeSizeClass c);     // "small", "medium", "large", "very large"
const char* size_class_range(SinkholeSizeClass c);    // "< 2 m", "2-5 m", "5-15 m", "> 15 m"

// One blanket layer, listed from the cavity upward.
struct BlanketLayer {
  double thickness = 0.0;          // m, >= 0
  double angle_of_draw_deg = 0.0;  // from the vertical, in [0, 90)
};

// "THICKNESS:ANGLE" ("12:30", "12m:30", "1500mm:20.5"); the thickness takes a length unit (m default).
// With `angle_only`, the text may also be ":ANGLE" or "ANGLE" (the thickness then comes from elsewhere,
// returned as NaN). Throws InputError naming `what` ("--layer") on malformed text or bad values.
BlanketLayer parse_layer(std::string_view text, std::string_view what = "--layer", bool angle_only = false);

struct LayerContribution {
  BlanketLayer layer;
  double widening = 0.0;        // m, 2 t tan(alpha): the layer's share of D_s
  double diameter_above = 0.0;  // m, the cone's diameter at the layer's top
};

struct SuppositionEstimate {
  double throat = 0.0;                    // m
  std::vector<LayerContribution> layers;  // cavity upward
  double total_thickness = 0.0;           // m, the cavity's depth below surface
  double surface_diameter = 0.0;          // m
  SinkholeSizeClass size_class = SinkholeSizeClass::small;
};

// D_s = D_throat + 2 sum t_i tan(alpha_i). Throws InputError for a throat <= 0, no layers, a negative
// thickness or an angle outside [0, 90).
SuppositionEstimate scenario_supposition(double throat, const std::vector<BlanketLayer>& layers);

// The single angle of draw (from the vertical) that widens a throat B to a surface diameter D through a
// thickness H: atan((D - B) / (2 H)) in degrees (negative if D < B).
double implied_angle_of_draw_deg(double surface_diameter, double throat, double thickness);

// What a DEM run says, in model units (study/sinkhole_run.hpp reads it from a run folder's
// resolved.toml and analysis/metrics.json).
struct DemRunGeometry {
  std::string name;
  double g_level = 1.0;              // N, spin_up.g_level
  double trapdoor_width = 0.0;       // m, B
  double soil_height = 0.0;          // m, H: the measured surface height above the trapdoor
                                     //   (zone_of_influence.surface_height_m), else pluviation.fill_height
  std::string soil_height_source;    // which of the two
  double fill_height = 0.0;          // m, pluviation.fill_height (0: the pour ended by count)
  double surface_zone_width = 0.0;   // m, zone_of_influence.surface_width_m (NaN if not found)
  double settlement_fraction = 0.0;  // the zone's threshold as a fraction of the trapdoor travel
  double travel = 0.0;               // m, trapdoor travel analysed (trapdoor.travel_m)
  double band_left_deg = 0.0;        // band angles to the vertical, positive outward (NaN if not found)
  double band_right_deg = 0.0;
  // The analysis' warnings (metrics.json `warnings`), e.g. a zone of influence that reaches a side
  // wall: the surface zone, and so the DEM sinkhole size, is then bounded by the box, not the soil.
  std::vector<std::string> warnings;
};

struct MechanismComparison {
  DemRunGeometry run;
  // Prototype scale (model x N), metres.
  double throat = 0.0;                 // B x N
  double thickness = 0.0;              // H x N
  double dem_surface_diameter = 0.0;   // surface zone of influence x N
  SinkholeSizeClass dem_size_class = SinkholeSizeClass::small;
  double angle_from_surface_deg = 0.0; // atan((D_dem - B) / (2 H)), scale-free
  double angle_from_bands_deg = 0.0;   // mean of the left and right band angles (NaN if neither)
  // The supposition for the same geometry with the given angle of draw (one layer).
  double assumed_angle_deg = 0.0;
  SuppositionEstimate supposition;
  double ratio = 0.0;                  // supposition D_s / DEM D_s
};

MechanismComparison compare_with_dem(const DemRunGeometry& run, double assumed_angle_of_draw_deg);

}  // namespace trapdem
