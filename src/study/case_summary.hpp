#pragma once
// One case of a study in numbers: the mechanism metrics of its analysis (analysis/metrics.json), its
// ground reaction curve (trapdoor.csv), its cost (run.json) and the sinkhole estimates. The report's
// table, findings and summary.json are made from these, so what they say is what the runs measured.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/json.hpp"
#include "analysis/sinkhole.hpp"
#include "experiment/ground_reaction.hpp"

namespace trapdem {

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

struct CaseCost {
  double wall_seconds = kMissing;      // s, summed over the run's segments (run.json)
  double particle_steps = kMissing;
  double particle_steps_per_second = kMissing;
  double particles = kMissing;         // at the end
  double segments = kMissing;          // 1 + the number of resumes
};

struct CaseSummary {
  std::string name, label;
  bool replicate = false;              // one of several packing seeds of the case (study/replicates.hpp)
  std::uint64_t seed = 0;              // its pluviation.seed (a replicate's; 0 otherwise)
  double trapdoor_width = kMissing;    // m, B
  double travel = kMissing;            // m, trapdoor travel analysed (the final snapshot)
  double mean_diameter = kMissing;     // m, d of the viewed particles
  // Shear bands: mean of the left and right band (the one found if only one), and each side.
  double band_angle_deg = kMissing, band_angle_left_deg = kMissing, band_angle_right_deg = kMissing;
  // Their uncertainty: the standard error of the fitted slope (metrics.json angle_error_deg); of the
  // mean of both sides, (e_l^2 + e_r^2)^(1/2) / 2 (independent fits).
  double band_angle_error_deg = kMissing, band_angle_left_error_deg = kMissing, band_angle_right_error_deg = kMissing;
  double band_height = kMissing;       // m above the trapdoor, height the bands reach
  double band_width_d = kMissing;      // band width in mean diameters
  // Zone of influence (surface settlement above a fraction of the travel).
  double zone_surface = kMissing;      // m
  double zone_mid_height = kMissing;   // m
  double shape_ratio = kMissing;       // zone width at mid-height / B (~1 columnar, > 1.3 elliptical)
  double zone_surface_25 = kMissing;     // m, the zone at 25 % of the travel, at the surface
  double zone_mid_height_25 = kMissing;  // m, and at mid-height
  double gamma_max_p90 = kMissing;       // the 90th percentile of the total gamma_max over the triangles
  double volumetric_beside_walls = kMissing;  // the far field's volumetric strain, both walls' mean
  std::string shape;                   // "elliptical", "chimney", ... as the analysis calls it
  // Ground reaction curve: the trapdoor's stress over its value before lowering.
  double min_load_ratio = kMissing;    // the least (maximum arching)
  double min_load_at_over_b = kMissing;// delta/B where it occurs
  double final_load_ratio = kMissing;  // at the end of the travel
  std::vector<double> grc_x_over_b, grc_trapdoor_ratio;
  CaseCost cost;
  // How large can the sinkhole get (prototype scale): NaN where the run lacks what it needs.
  double dem_surface_diameter = kMissing;        // m, zone at the surface x g level
  double supposition_surface_diameter = kMissing;// m, with the report's angle of draw
  double angle_from_surface_deg = kMissing;      // the angle of draw the DEM surface zone implies
  std::string dem_size_class, supposition_size_class;
  // The analysis' warnings (metrics.json `warnings`, e.g. a zone of influence reaching a side wall).
  std::vector<std::string> warnings;
  // The case's element test (report.element_test), per case, not per replicate: degrees.
  double phi_peak_deg = kMissing, phi_cs_deg = kMissing;
};

// The numeric fields of a summary under their JSON/CSV names, in the order the report's files list
// them: summary.json, metrics.csv and the per-case spreads all follow this one list.
struct SummaryMetric {
  const char* key;
  double CaseSummary::*field;
};
const std::vector<SummaryMetric>& summary_metrics();

// Fills the mechanism fields from a metrics.json document (NaN where a value is missing or null).
void read_mechanism_metrics(const Json& metrics, CaseSummary& summary);
// Fills the ground reaction fields from trapdoor.csv rows (B in m).
void read_ground_reaction(const std::vector<GroundReactionRow>& rows, double trapdoor_width, CaseSummary& summary);
// Reads run.json if the folder has one (a missing file leaves the cost NaN).
CaseCost read_case_cost(const std::filesystem::path& run_dir);
void read_sinkhole_comparison(const MechanismComparison& comparison, CaseSummary& summary);

// A case as a JSON object (NaN as null), for the report's summary.json.
Json to_json(const CaseSummary& summary);

}  // namespace trapdem
