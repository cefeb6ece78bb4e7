#pragma once
// A PIV output folder for the comparison tests: piv.h5 with the datasets `trapdem compare` reads
// (docs/piv.md: grid step, the pixel -> model matrix and unit, per image its name, model position,
// vertical displacement and validity), as a 0.5 mm/px camera over the synthetic run's box (pixel
// (0, 0) at model (0, 140) mm) sees subsets every 8 px moved by a known settlement field. Written
// through io/ so the study tests need not link the PIV module; that the PIV module's own writer
// and this reader agree is tests/piv/piv_h5_reading_test.cpp.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/point_set.hpp"
#include "io/hdf5_file.hpp"

namespace trapdem::test {

// `w(p, delta)`: vertical displacement (m, up positive) of box point p at trapdoor displacement delta.
inline void write_synthetic_piv(const std::filesystem::path& dir, const std::vector<double>& deltas,
                                const std::function<double(Point2, double)>& w) {
  std::filesystem::create_directories(dir);
  const double mm_per_px = 0.5, top_mm = 140.0;
  Hdf5File file = Hdf5File::create(dir / "piv.h5");
  const Hdf5Group grid = file.create_group("grid");
  grid.set_int_attribute("step", 8);
  const Hdf5Group model = file.create_group("model");
  model.write_doubles("pixel_to_model", std::vector<double>{mm_per_px, 0.0, 0.0, 0.0, -mm_per_px, top_mm, 0.0, 0.0, 1.0});
  model.set_string_attribute("unit", "mm");
  const Hdf5Group images = file.create_group("images");
  for (std::size_t k = 0; k < deltas.size(); ++k) {
    const Hdf5Group g = images.create_group(fmt::format("{:06d}", k + 1));
    g.set_string_attribute("name", fmt::format("/somewhere/camera/{:03d}_{:g}mm.png", k, deltas[k] * 1e3));
    std::vector<double> x, z, dz;
    for (int py = 8; py <= 272; py += 8) {
      for (int px = 8; px <= 392; px += 8) {
        const Point2 p{px * mm_per_px * 1e-3, (top_mm - py * mm_per_px) * 1e-3};  // m, box coordinates
        const double w_mm = deltas[k] > 0.0 ? w(p, deltas[k]) * 1e3 : 0.0;
        x.push_back(p.x * 1e3);
        z.push_back(p.z * 1e3 + w_mm);  // where the subset is in this image
        dz.push_back(w_mm);
      }
    }
    g.write_doubles("x_model", x, "mm");
    g.write_doubles("z_model", z, "mm");
    g.write_doubles("w_model", dz, "mm");
    g.write_uint8s("valid", std::vector<std::uint8_t>(dz.size(), 1));
  }
}

}  // namespace trapdem::test
