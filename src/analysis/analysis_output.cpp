#include "analysis/analysis_output.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/mechanism_shape.hpp"
#include "core/length_text.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

void create_parent(const fs::path& file) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
}

Json trace_json(const std::vector<BandTracePoint>& points) {
  Json z = Json::array(), x = Json::array(), peak = Json::array(), width = Json::array();
  for (const auto& p : points) {
    z.push_back(p.z);
    x.push_back(p.x);
    peak.push_back(p.peak);
    width.push_back(p.horizontal_width);
  }
  Json trace = Json::object();
  trace.set("z_m", z);
  trace.set("x_m", x);
  trace.set("peak_gamma_max_smoothed", peak);
  trace.set("horizontal_width_m", width);
  return trace;
}

Json band_json(const ShearBand& band, const AnalysisResult& r) {
  const double B = r.geometry.trapdoor.width;
  Json b = Json::object();
  b.set("angle_deg", band.angle_deg);
  b.set("angle_error_deg", band.angle_error_deg);
  b.set("base_angle_deg", band.base_angle_deg);
  b.set("base_angle_error_deg", band.base_angle_error_deg);
  b.set("height_reached_m", band.height_reached);
  b.set("height_reached_over_B", band.height_reached / B);
  b.set("end", band_end_name(band.end));
  b.set("width_diameters", band.width_diameters);
  b.set("trace_points", band.trace.size());
  b.set("trace", trace_json(band.trace));
  Json branches = Json::array();
  for (const auto& branch : band.branches) {
    Json e = Json::object();
    e.set("height_m", branch.height);
    e.set("height_over_B", branch.height / B);
    e.set("angle_deg", branch.angle_deg);
    e.set("angle_error_deg", branch.angle_error_deg);
    e.set("top_m", branch.trace.back().z - r.geometry.trapdoor.base_z);
    e.set("trace", trace_json(branch.trace));
    branches.push_back(e);
  }
  b.set("branches", branches);
  return b;
}

// The side-wall warning in words, with its numbers; empty when there is none.
std::string side_wall_warning_text(const AnalysisResult& r) {
  const ZoneOfInfluence& z = r.zone;
  if (!z.wall_warning) return {};
  const double B = r.geometry.trapdoor.width, travel = r.trapdoor_travel();
  const double span = z.wall_right_x - z.wall_left_x;
  return fmt::format(
      "the zone of influence {} the side walls: settlement beside the walls {} mm (left) and {} mm (right) = "
      "{:.1f} % / {:.1f} % of the trapdoor travel (zone threshold {:.1f} %, warning at {:.1f} %); surface zone "
      "{:.2f} B wide in a {:.2f} B box, its edges {:.2f} B and {:.2f} B from the walls. Widths and a sinkhole size "
      "read from this run are bounded by the box",
      z.reaches_wall ? "reaches" : "is close to", fmt::format("{:.2f}", z.wall_settlement_left * 1e3),
      fmt::format("{:.2f}", z.wall_settlement_right * 1e3), 100.0 * z.wall_settlement_left / travel,
      100.0 * z.wall_settlement_right / travel, 100.0 * r.settings.zone.settlement_fraction,
      100.0 * r.settings.zone.settlement_fraction * r.settings.zone.wall_warning_fraction, z.surface_width / B,
      span / B, (z.surface_left - z.wall_left_x) / B, (z.wall_right_x - z.surface_right) / B);
}

std::vector<double> component(const std::vector<PlaneStrain>& strains, double PlaneStrain::*member) {
  std::vector<double> out;
  out.reserve(strains.size());
  for (const auto& e : strains) out.push_back(e.*member);
  return out;
}

}  // namespace

Json metrics_json(const AnalysisResult& r) {
  const double B = r.geometry.trapdoor.width;
  Json j = Json::object();
  j.set("case", r.geometry.name);
  Json inputs = Json::object();
  inputs.set("at_m", r.at_displacement);
  inputs.set("reference_m", r.reference_displacement);
  inputs.set("at_requested_m", r.settings.at);
  inputs.set("reference_requested_m", r.settings.reference);
  inputs.set("at_snapshot", r.at_label);
  inputs.set("reference_snapshot", r.reference_label);
  inputs.set("view", view_name(r.settings.view));
  inputs.set("front_depth_m", r.settings.view == ViewKind::front ? Json(r.settings.front_depth) : Json());
  inputs.set("incremental", r.has_incremental);
  inputs.set("increments", r.has_incremental ? Json(r.accumulated.increments) : Json());
  inputs.set("grid_spacing_m", r.settings.grid_spacing);
  inputs.set("strain_for_metrics", "total");
  j.set("inputs", inputs);

  Json trapdoor = Json::object();
  trapdoor.set("centre_x_m", r.geometry.trapdoor.centre_x);
  trapdoor.set("width_m", B);
  trapdoor.set("travel_m", r.trapdoor_travel());
  trapdoor.set("travel_over_B", r.trapdoor_travel() / B);
  j.set("trapdoor", trapdoor);

  Json particles = Json::object();
  particles.set("matched", r.matched_particles);
  particles.set("viewed", r.id.size());
  particles.set("mean_diameter_m", r.mean_diameter);
  particles.set("max_diameter_m", r.max_diameter);
  j.set("particles", particles);

  Json triangles = Json::object();
  triangles.set("delaunay", r.delaunay_triangles);
  triangles.set("kept", r.mesh.mesh.size());
  triangles.set("dropped_long_edge", r.mesh.dropped_long_edge);
  triangles.set("dropped_sliver", r.mesh.dropped_sliver);
  triangles.set("max_edge_in_diameters", r.settings.filter.max_edge_in_diameters);
  triangles.set("min_angle_deg", r.settings.filter.min_angle_deg);
  j.set("triangles", triangles);

  Json strain = Json::object();
  strain.set("sign_convention", "compression positive; gamma_max engineering shear");
  strain.set("gamma_max_median", quantile(r.gamma_max, 0.5));
  strain.set("gamma_max_p25", quantile(r.gamma_max, 0.25));
  strain.set("gamma_max_p75", quantile(r.gamma_max, 0.75));
  strain.set("gamma_max_p90", quantile(r.gamma_max, 0.90));
  strain.set("gamma_max_p95", quantile(r.gamma_max, 0.95));
  strain.set("gamma_max_p99", quantile(r.gamma_max, 0.99));
  strain.set("gamma_max_max", quantile(r.gamma_max, 1.0));
  strain.set("volumetric_median", quantile(r.volumetric, 0.5));
  strain.set("percentiles", "over the kept triangles, each counted once (not area-weighted)");
  strain.set("volumetric_beside_left_wall", r.volumetric_beside_left_wall);
  strain.set("volumetric_beside_right_wall", r.volumetric_beside_right_wall);
  strain.set("beside_wall", "area-weighted mean over the kept triangles within one trapdoor width of the side wall's outermost particles");
  if (r.has_incremental) {
    strain.set("gamma_max_incremental_p95", quantile(r.gamma_max_incremental, 0.95));
    strain.set("gamma_max_incremental_max", quantile(r.gamma_max_incremental, 1.0));
  }
  j.set("strain", strain);

  Json bands = Json::object();
  bands.set("angle_convention", "degrees to the vertical, positive leaning outward (zone widening upward)");
  bands.set("angle_error", "standard error of the fitted slope (residual autocorrelation corrected), degrees");
  bands.set("ridge_threshold", r.settings.bands.ridge_threshold);
  bands.set("smoothing_diameters", r.settings.bands.smoothing_diameters);
  bands.set("smoothing_m", r.settings.bands.smoothing_diameters * r.mean_diameter);
  bands.set("left", band_json(r.bands.left, r));
  bands.set("right", band_json(r.bands.right, r));
  j.set("shear_bands", bands);

  Json zone = Json::object();
  zone.set("settlement_fraction", r.settings.zone.settlement_fraction);
  zone.set("threshold_m", r.zone.threshold);
  zone.set("surface_height_m", r.zone.surface_height);
  zone.set("surface_width_m", r.zone.surface_width);
  zone.set("surface_width_over_B", r.zone.surface_width / B);
  Json widths = Json::array();
  for (const auto& w : r.zone.widths) {
    Json e = Json::object();
    e.set("height_m", w.height);
    e.set("width_m", w.width);
    e.set("width_over_B", w.width / B);
    widths.push_back(e);
  }
  zone.set("widths", widths);
  zone.set("mid_height_width_m", r.zone.mid_height_width);
  zone.set("shape_ratio", r.zone.shape_ratio);
  Json at_fractions = Json::array();
  for (std::size_t k = 0; k < r.zone_at_fractions.size(); ++k) {
    const ZoneOfInfluence& z = r.zone_at_fractions[k];
    Json one = Json::object();
    one.set("settlement_fraction", kZoneFractions[k]);
    one.set("threshold_m", z.threshold);
    one.set("surface_width_m", z.surface_width);
    one.set("mid_height_width_m", z.mid_height_width);
    one.set("shape_ratio", z.shape_ratio);
    at_fractions.push_back(one);
  }
  zone.set("at_higher_thresholds", at_fractions);
  zone.set("shape", mechanism_shape_name(r.shape.shape));
  zone.set("shape_from", mechanism_shape_basis_name(r.shape.basis));
  const double travel = r.trapdoor_travel();
  Json wall = Json::object();
  wall.set("warning", r.zone.wall_warning);
  wall.set("reaches_wall", r.zone.reaches_wall);
  wall.set("warning_fraction_of_threshold", r.settings.zone.wall_warning_fraction);
  wall.set("settlement_left_m", r.zone.wall_settlement_left);
  wall.set("settlement_right_m", r.zone.wall_settlement_right);
  wall.set("settlement_left_over_travel", r.zone.wall_settlement_left / travel);
  wall.set("settlement_right_over_travel", r.zone.wall_settlement_right / travel);
  wall.set("surface_zone_left_m", r.zone.surface_left);
  wall.set("surface_zone_right_m", r.zone.surface_right);
  wall.set("wall_left_m", r.zone.wall_left_x);
  wall.set("wall_right_m", r.zone.wall_right_x);
  wall.set("edge_to_wall_left_over_B", (r.zone.surface_left - r.zone.wall_left_x) / B);
  wall.set("edge_to_wall_right_over_B", (r.zone.wall_right_x - r.zone.surface_right) / B);
  wall.set("box_span_over_B", (r.zone.wall_right_x - r.zone.wall_left_x) / B);
  zone.set("side_walls", wall);
  j.set("zone_of_influence", zone);

  // Everything a reader of the numbers must know first (the study report and `sinkhole --from`
  // read this list).
  Json warnings = Json::array();
  if (const std::string text = side_wall_warning_text(r); !text.empty()) warnings.push_back(text);
  for (const std::string& text : r.unmatched_ids) warnings.push_back(text);
  j.set("warnings", warnings);
  return j;
}

void write_metrics(const fs::path& path, const AnalysisResult& result) {
  create_parent(path);
  write_text_atomically(path, metrics_json(result).dump());
}

void write_fields(const fs::path& h5, const fs::path& xmf, const AnalysisResult& r) {
  if (h5.parent_path() != xmf.parent_path()) {
    throw std::invalid_argument("write_fields: " + xmf.string() + " names " + h5.string() + " by its file name");
  }
  create_parent(h5);
  write_atomically(h5, [&](const fs::path& temporary) {
    Hdf5File file = Hdf5File::create_in_memory(h5);
    file.set_string_attribute("format", "trapdem-analysis-fields");
    file.set_int_attribute("version", 1);
    file.set_string_attribute("case", r.geometry.name);
    file.set_string_attribute("reference_snapshot", r.reference_label);
    file.set_string_attribute("at_snapshot", r.at_label);
    file.set_double_attribute("reference_displacement", r.reference_displacement);
    file.set_double_attribute("at_displacement", r.at_displacement);
    file.set_string_attribute("view", view_name(r.settings.view));
    file.set_double_attribute("front_depth", r.settings.front_depth);
    file.set_double_attribute("mean_diameter", r.mean_diameter);
    file.set_string_attribute("sign_convention", "strain compression positive; gamma engineering shear");

    const std::size_t n = r.id.size();
    std::vector<Vec3> position(n), displacement(n);
    for (std::size_t k = 0; k < n; ++k) {
      position[k] = {r.points.position[k].x, r.geometry.box_depth, r.points.position[k].z};
      displacement[k] = {r.points.displacement[k].x, 0.0, r.points.displacement[k].z};
    }
    const Hdf5Group nodes = file.create_group("nodes");
    nodes.write_int64s("id", r.id);
    nodes.write_vec3s("position", position, "m");
    nodes.write_vec3s("displacement", displacement, "m");
    nodes.write_doubles("vertical_displacement", vertical_displacements(r.points), "m");
    nodes.write_doubles("radius", r.radius, "m");

    const Hdf5Group tri = file.create_group("triangles");
    std::vector<Int3> connectivity;
    connectivity.reserve(r.mesh.mesh.size());
    for (const auto& t : r.mesh.mesh.triangles) {
      connectivity.push_back({static_cast<std::int32_t>(t[0]), static_cast<std::int32_t>(t[1]),
                              static_cast<std::int32_t>(t[2])});
    }
    tri.write_int3s("connectivity", connectivity);
    tri.write_doubles("gamma_max", r.gamma_max);
    tri.write_doubles("volumetric_strain", r.volumetric);
    tri.write_doubles("exx", component(r.strain, &PlaneStrain::exx));
    tri.write_doubles("ezz", component(r.strain, &PlaneStrain::ezz));
    tri.write_doubles("gamma_xz", component(r.strain, &PlaneStrain::gamma_xz));
    tri.write_doubles("gamma_max_smoothed", r.gamma_max_smoothed);
    if (r.has_incremental) {
      tri.write_doubles("gamma_max_incremental", r.gamma_max_incremental);
      tri.write_doubles("volumetric_strain_incremental", r.volumetric_incremental);
      tri.write_doubles("exx_incremental", component(r.accumulated.strain, &PlaneStrain::exx));
      tri.write_doubles("ezz_incremental", component(r.accumulated.strain, &PlaneStrain::ezz));
      tri.write_doubles("gamma_xz_incremental", component(r.accumulated.strain, &PlaneStrain::gamma_xz));
    }

    const Hdf5Group grid = file.create_group("grid");
    const GridSpec& g = r.vertical_displacement.grid;
    grid.set_double_attribute("x0", g.x0);
    grid.set_double_attribute("z0", g.z0);
    grid.set_double_attribute("spacing", g.spacing);
    grid.set_int_attribute("nx", static_cast<std::int64_t>(g.nx));
    grid.set_int_attribute("nz", static_cast<std::int64_t>(g.nz));
    grid.write_doubles("vertical_displacement", r.vertical_displacement.value, "m");

    const Hdf5Group bands = file.create_group("bands");
    const auto write_trace = [](const Hdf5Group& g, const std::vector<BandTracePoint>& trace) {
      std::vector<double> z, x, peak, width;
      for (const auto& p : trace) {
        z.push_back(p.z);
        x.push_back(p.x);
        peak.push_back(p.peak);
        width.push_back(p.horizontal_width);
      }
      g.write_doubles("z", z, "m");
      g.write_doubles("x", x, "m");
      g.write_doubles("peak_gamma_max", peak);
      g.write_doubles("horizontal_width", width, "m");
    };
    bands.set_double_attribute("smoothing_diameters", r.settings.bands.smoothing_diameters);
    for (const ShearBand* band : {&r.bands.left, &r.bands.right}) {
      const Hdf5Group b = bands.create_group(band->side == BandSide::left ? "left" : "right");
      write_trace(b, band->trace);
      b.set_double_attribute("angle_deg", band->angle_deg);
      b.set_double_attribute("angle_error_deg", band->angle_error_deg);
      b.set_double_attribute("base_angle_deg", band->base_angle_deg);
      b.set_double_attribute("height_reached", band->height_reached);
      b.set_string_attribute("end", band_end_name(band->end));
      b.set_double_attribute("width_diameters", band->width_diameters);
      for (std::size_t k = 0; k < band->branches.size(); ++k) {
        const BandBranch& branch = band->branches[k];
        const Hdf5Group g = b.create_group(fmt::format("branch_{}", k));
        write_trace(g, branch.trace);
        g.set_double_attribute("height", branch.height);
        g.set_double_attribute("angle_deg", branch.angle_deg);
        g.set_double_attribute("angle_error_deg", branch.angle_error_deg);
      }
    }
    file.write_image(temporary);
  });
  write_text_atomically(xmf, fields_xdmf(r, h5.filename().string()));
}

std::string fields_xdmf(const AnalysisResult& r, const std::string& h5) {
  const std::size_t n = r.id.size(), m = r.mesh.mesh.size();
  std::string s;
  s += "<?xml version=\"1.0\" ?>\n";
  s += "<!-- trapdem analysis: constant strain triangles on the reference particle centres; data in " + h5 +
       " (see docs/analysis.md). Strain compression positive. -->\n";
  s += "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  s += fmt::format("    <Grid Name=\"{} {} to {}\" GridType=\"Uniform\">\n", r.geometry.name,
                   format_mm(r.reference_displacement), format_mm(r.at_displacement));
  s += fmt::format("      <Topology TopologyType=\"Triangle\" NumberOfElements=\"{}\">\n", m);
  s += fmt::format("        <DataItem Dimensions=\"{} 3\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">{}:/triangles/connectivity</DataItem>\n", m, h5);
  s += "      </Topology>\n";
  s += "      <Geometry GeometryType=\"XYZ\">\n";
  s += fmt::format("        <DataItem Dimensions=\"{} 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:/nodes/position</DataItem>\n", n, h5);
  s += "      </Geometry>\n";
  auto cell = [&](const std::string& name) {
    s += fmt::format("      <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n", name);
    s += fmt::format("        <DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:/triangles/{}</DataItem>\n", m, h5, name);
    s += "      </Attribute>\n";
  };
  for (const char* name : {"gamma_max", "gamma_max_smoothed", "volumetric_strain", "exx", "ezz", "gamma_xz"}) cell(name);
  if (r.has_incremental) {
    for (const char* name : {"gamma_max_incremental", "volumetric_strain_incremental"}) cell(name);
  }
  // Node attributes; id and radius are the particles at the nodes, to match them with snapshots.h5
  // or draw them as spheres.
  auto node = [&](const char* name, const char* kind, const char* dims, const char* type) {
    s += fmt::format("      <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n", name, kind);
    s += fmt::format("        <DataItem Dimensions=\"{}{}\" NumberType=\"{}\" Precision=\"8\" Format=\"HDF\">{}:/nodes/{}</DataItem>\n",
                     n, dims, type, h5, name);
    s += "      </Attribute>\n";
  };
  node("displacement", "Vector", " 3", "Float");
  node("vertical_displacement", "Scalar", "", "Float");
  node("id", "Scalar", "", "Int");
  node("radius", "Scalar", "", "Float");
  s += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return s;
}

std::string metrics_table(const AnalysisResult& r) {
  const double B = r.geometry.trapdoor.width, d = r.mean_diameter;
  auto num = [](double v, const char* f) { return std::isfinite(v) ? fmt::format(fmt::runtime(f), v) : std::string("-"); };
  std::string s;
  s += fmt::format("analysis of '{}': trapdoor {} -> {} (travel {} = {:.3f} B), {} view, {} particles, d = {}\n",
                   r.geometry.name, format_mm(r.reference_displacement), format_mm(r.at_displacement),
                   format_mm(r.trapdoor_travel()), r.trapdoor_travel() / B, view_name(r.settings.view), r.id.size(),
                   format_mm(d));
  s += fmt::format("  triangles: {} kept of {} (dropped {} long-edge, {} sliver)\n", r.mesh.mesh.size(),
                   r.delaunay_triangles, r.mesh.dropped_long_edge, r.mesh.dropped_sliver);
  s += fmt::format("  shear bands (traced on gamma_max smoothed over {:g} d; angle +- standard error of the fit)\n",
                   r.settings.bands.smoothing_diameters);
  s += "  band     angle(deg)       base angle(deg)  height(mm)  height/B  width(d)  end\n";
  const auto with_error = [&](double v, double e) {
    if (!std::isfinite(v)) return std::string("-");
    return std::isfinite(e) ? fmt::format("{:.1f} +- {:.1f}", v, e) : fmt::format("{:.1f} +- ?", v);
  };
  for (const ShearBand* b : {&r.bands.left, &r.bands.right}) {
    s += fmt::format("  {:<7} {:>14} {:>18} {:>11} {:>9} {:>9}  {}\n", b->side == BandSide::left ? "left" : "right",
                     with_error(b->angle_deg, b->angle_error_deg), with_error(b->base_angle_deg, b->base_angle_error_deg),
                     num(b->height_reached * 1e3, "{:.1f}"), num(b->height_reached / B, "{:.2f}"),
                     num(b->width_diameters, "{:.1f}"), band_end_name(b->end));
    for (const auto& branch : b->branches) {
      s += fmt::format("    branch leaving at {} mm, to {} mm, angle {} deg\n", num(branch.height * 1e3, "{:.1f}"),
                       num((branch.trace.back().z - r.geometry.trapdoor.base_z) * 1e3, "{:.1f}"),
                       with_error(branch.angle_deg, branch.angle_error_deg));
    }
  }
  s += fmt::format("  zone of influence (settlement >= {:.0f}% of travel): surface {} mm ({} B)", 
                   100.0 * r.settings.zone.settlement_fraction, num(r.zone.surface_width * 1e3, "{:.1f}"),
                   num(r.zone.surface_width / B, "{:.2f}"));
  for (const auto& w : r.zone.widths) {
    s += fmt::format(", at {} mm {} mm", num(w.height * 1e3, "{:.0f}"), num(w.width * 1e3, "{:.1f}"));
  }
  s += fmt::format("; shape ratio {} (mid-height width / B); {}{}\n", num(r.zone.shape_ratio, "{:.2f}"),
                   mechanism_shape_name(r.shape.shape),
                   r.shape.basis == MechanismShapeBasis::bands ? " (both bands vertical to the surface)" : "");
  if (const std::string text = side_wall_warning_text(r); !text.empty()) s += "  WARNING: " + text + "\n";
  for (const std::string& text : r.unmatched_ids) s += "  WARNING: " + text + "\n";
  return s;
}

}  // namespace trapdem
