#include "experiment/element_output.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace trapdem {

namespace {

// A JSON number; NaN and infinities (no dilatancy slope, say) as null.
std::string number(double x) { return std::isfinite(x) ? fmt::format("{:.6g}", x) : "null"; }

// A JSON string of a configuration name (quotes and backslashes escaped).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

std::string vec(const Vec3& v) { return fmt::format("[{}, {}, {}]", number(v.x), number(v.y), number(v.z)); }

}  // namespace

std::vector<ElementAngles> element_angles(const ElementResult& result) {
  std::vector<ElementAngles> out;
  for (double confining : result.settings.confining) {
    const SpecimenResult* dense = nullptr;
    const SpecimenResult* loose = nullptr;
    for (const SpecimenResult& s : result.specimens) {
      if (s.confining != confining) continue;
      if (s.packing == Packing::dense) dense = &s;
      if (s.packing == Packing::loose) loose = &s;
    }
    if (!dense || !loose) continue;
    out.push_back({confining, dense->phi_peak, 0.5 * (dense->phi_cs + loose->phi_cs),
                   std::fabs(dense->phi_cs - loose->phi_cs)});
  }
  return out;
}

std::string element_csv(const ElementResult& result) {
  std::string out =
      "packing,confining_Pa,axial_strain,deviator_Pa,mean_stress_Pa,stress_ratio_q_over_p,sin_phi_mobilised,"
      "volumetric_strain,coordination_number,inertial_number,wall_sxx_Pa,wall_syy_Pa,wall_szz_Pa,contact_sxx_Pa,"
      "contact_syy_Pa,contact_szz_Pa,contact_mean_stress_Pa,interior_sxx_Pa,interior_syy_Pa,interior_szz_Pa,"
      "interior_sin_phi\n";
  for (const SpecimenResult& s : result.specimens) {
    for (const ElementRow& r : s.rows) {
      const double lw_mean = (r.love_weber_stress.x + r.love_weber_stress.y + r.love_weber_stress.z) / 3.0;
      out += fmt::format("{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4f},{:.4g},{:.6g},{:.6g},{:.6g},{:.6g},"
                         "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
                         to_string(s.packing), s.confining, r.axial_strain, r.deviator, r.mean_stress,
                         r.deviator / r.mean_stress, r.sin_phi, r.volumetric_strain, r.coordination,
                         r.inertial_number, r.wall_stress.x, r.wall_stress.y, r.wall_stress.z,
                         r.love_weber_stress.x, r.love_weber_stress.y, r.love_weber_stress.z, lw_mean,
                         r.interior_stress.x, r.interior_stress.y, r.interior_stress.z, r.interior_sin_phi);
    }
  }
  return out;
}

std::string element_json(const ElementResult& result) {
  const ElementSettings& e = result.settings;
  std::string out = "{\n";
  out += fmt::format("  \"configuration\": {},\n", quoted(result.name));
  out += fmt::format("  \"test\": \"{}\",\n", to_string(e.kind));
  out += fmt::format("  \"particles\": {},\n", e.particles);
  out += fmt::format("  \"mean_diameter_m\": {},\n", number(result.mean_diameter));
  out += fmt::format("  \"time_step_s\": {},\n", number(result.time_step));
  out += fmt::format("  \"inertial_number\": {},\n", number(e.inertial_number));
  out += fmt::format("  \"max_axial_strain\": {},\n", number(e.max_axial_strain));
  out += fmt::format("  \"critical_state_window\": {},\n", number(e.critical_state_window));
  out += fmt::format("  \"interior_margin_diameters\": {},\n", number(e.interior_margin));
  out += "  \"angles\": [";
  const std::vector<ElementAngles> angles = element_angles(result);
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const ElementAngles& a = angles[k];
    out += fmt::format("{}\n    {{\"confining_Pa\": {}, \"phi_peak_deg\": {}, \"phi_cs_deg\": {}, "
                       "\"phi_cs_dense_loose_gap_deg\": {}}}",
                       k ? "," : "", number(a.confining), number(a.phi_peak), number(a.phi_cs), number(a.phi_cs_gap));
  }
  out += angles.empty() ? "],\n" : "\n  ],\n";
  out += "  \"specimens\": [";
  for (std::size_t k = 0; k < result.specimens.size(); ++k) {
    const SpecimenResult& s = result.specimens[k];
    const IsotropicState& iso = s.isotropic;
    out += fmt::format("{}\n    {{\n", k ? "," : "");
    out += fmt::format("      \"packing\": \"{}\",\n", to_string(s.packing));
    out += fmt::format("      \"confining_Pa\": {},\n", number(s.confining));
    out += fmt::format("      \"axial_strain_rate_per_s\": {},\n", number(s.strain_rate));
    out += fmt::format("      \"initial_solid_fraction\": {},\n", number(iso.solid_fraction));
    out += fmt::format("      \"initial_void_ratio\": {},\n", number(iso.void_ratio));
    out += fmt::format("      \"initial_coordination_number\": {},\n", number(iso.coordination));
    out += fmt::format("      \"isotropic_wall_stress_Pa\": {},\n", vec(iso.wall_stress));
    out += fmt::format("      \"isotropic_contact_stress_Pa\": {},\n", vec(iso.love_weber_stress));
    out += fmt::format("      \"isotropic_contact_over_wall_mean_stress\": {},\n",
                       number(iso.love_weber_mean() / iso.wall_mean()));
    out += fmt::format("      \"isotropic_max_axis_error\": {},\n", number(iso.max_axis_error));
    out += fmt::format("      \"preparation_steps\": {},\n", iso.steps);
    out += fmt::format("      \"phi_peak_deg\": {},\n", number(s.phi_peak));
    out += fmt::format("      \"axial_strain_at_peak\": {},\n", number(s.axial_strain_at_peak));
    out += fmt::format("      \"phi_cs_deg\": {},\n", number(s.phi_cs));
    out += fmt::format("      \"phi_cs_scatter_deg\": {},\n", number(s.phi_cs_scatter));
    out += fmt::format("      \"phi_cs_interior_deg\": {},\n", number(s.phi_cs_interior));
    out += fmt::format("      \"dilatancy_angle_at_peak_deg\": {},\n", number(s.psi_peak));
    out += fmt::format("      \"max_lateral_stress_error\": {},\n", number(s.max_lateral_error));
    const ElementRow* last = s.rows.empty() ? nullptr : &s.rows.back();
    out += fmt::format("      \"final_volumetric_strain\": {},\n", number(last ? last->volumetric_strain : NAN));
    out += fmt::format("      \"final_contact_over_wall_mean_stress\": {}\n",
                       number(last ? (last->love_weber_stress.x + last->love_weber_stress.y +
                                      last->love_weber_stress.z) / 3.0 / last->mean_stress
                                   : NAN));
    out += "    }";
  }
  out += result.specimens.empty() ? "]\n" : "\n  ]\n";
  out += "}\n";
  return out;
}

void write_element_files(const std::filesystem::path& dir, const ElementResult& result) {
  write_text_atomically(dir / "element.csv", element_csv(result));
  write_text_atomically(dir / "element.json", element_json(result));
}

}  // namespace trapdem
