#include "piv/synthetic_sequence.hpp"

#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "piv/png_file.hpp"
#include "piv/speckle_synthesis.hpp"

namespace trapdem {

namespace fs = std::filesystem;

SyntheticField parse_synthetic_field(const std::string& text, const std::string& what) {
  for (SyntheticField f : {SyntheticField::rigid, SyntheticField::strain, SyntheticField::shear, SyntheticField::trapdoor})
    if (text == synthetic_field_name(f)) return f;
  throw InputError(fmt::format("{} '{}': rigid, strain, shear or trapdoor", what, text));
}

const char* synthetic_field_name(SyntheticField field) {
  switch (field) {
    case SyntheticField::rigid: return "rigid";
    case SyntheticField::strain: return "strain";
    case SyntheticField::shear: return "shear";
    case SyntheticField::trapdoor: return "trapdoor";
  }
  return "?";
}

SyntheticSequence write_synthetic_sequence(const SyntheticSequenceOptions& o) {
  if (o.out.empty()) throw InputError("synthetic images: an output folder is required");
  if (o.images < 2) throw InputError("--images: at least 2 (image 1 is undeformed)");
  if (o.width < 16 || o.height < 16)
    throw InputError(fmt::format("--size '{}x{}': at least 16x16 px", o.width, o.height));
  if (o.noise < 0.0) throw InputError("--noise must not be negative");
  SpeckleSettings st;
  st.width = o.width;
  st.height = o.height;
  st.noise_std = o.noise;
  st.seed = o.seed;
  const cv::Point2d centre{0.5 * (o.width - 1), 0.5 * (o.height - 1)};
  DisplacementField last;
  double magnitude = 0.0;
  TrapdoorSettlement t;
  switch (o.field) {
    case SyntheticField::rigid:
      magnitude = o.magnitude.value_or(2.5);
      last = rigid_shift(magnitude, 0.6 * magnitude);
      break;
    case SyntheticField::strain:
      magnitude = o.magnitude.value_or(0.01);
      last = uniform_strain(magnitude, -magnitude, centre);
      break;
    case SyntheticField::shear:
      magnitude = o.magnitude.value_or(0.01);
      last = simple_shear(magnitude, centre);
      break;
    case SyntheticField::trapdoor:
      magnitude = o.magnitude.value_or(8.0);
      t.centre_x = centre.x;
      t.width = 0.3 * o.width;
      t.base_y = 0.85 * o.height;
      t.settlement = magnitude;
      last = trapdoor_settlement(t);
      break;
  }
  std::vector<DisplacementField> fields;
  std::vector<double> factors;
  for (int k = 1; k < o.images; ++k) {
    const double f = static_cast<double>(k) / (o.images - 1);
    factors.push_back(f);
    fields.push_back(scaled(last, f));
  }
  const auto images = synthesize_speckle_sequence(st, fields);
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", o.out.string(), ec.message()));
  // truth.csv: one row per image, its prescribed field's parameters (docs/piv.md).
  std::string truth =
      "image,file,field,u_px,v_px,exx,eyy,gamma,settlement_px,origin_x_px,origin_y_px,trapdoor_centre_x_px,"
      "trapdoor_width_px,trapdoor_base_y_px,band_angle_deg,band_width_px,noise_std\n";
  const bool rigid = o.field == SyntheticField::rigid, strain = o.field == SyntheticField::strain,
             shear = o.field == SyntheticField::shear, trap = o.field == SyntheticField::trapdoor;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const std::string name = fmt::format("image_{:03d}.png", k + 1);
    write_png_atomically(o.out / name, images[k]);
    const double m = magnitude * (k == 0 ? 0.0 : factors[k - 1]);
    truth += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", k + 1, name,
                         synthetic_field_name(o.field), rigid ? m : 0.0, rigid ? 0.6 * m : 0.0, strain ? m : 0.0,
                         strain ? -m : 0.0, shear ? m : 0.0, trap ? m : 0.0, centre.x, centre.y,
                         trap ? t.centre_x : 0.0, trap ? t.width : 0.0, trap ? t.base_y : 0.0,
                         trap ? t.band_angle_deg : 0.0, trap ? t.band_width : 0.0, o.noise);
  }
  write_text_atomically(o.out / "truth.csv", truth);
  return {static_cast<int>(images.size()), magnitude};
}

}  // namespace trapdem
