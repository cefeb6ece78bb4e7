#include "piv/displacement_csv.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/errors.hpp"

namespace trapdem {

namespace {
void put(std::ostream& out, double value) {
  if (!std::isfinite(value)) {
    out << "nan";
    return;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  out << buffer;
}
}  // namespace

void write_displacements_csv(const PivResult& result, std::ostream& out) {
  out << "image,x_px,y_px,u_px,v_px,zncc,valid\n";
  for (std::size_t k = 0; k < result.image.size(); ++k) {
    const auto& subsets = result.image[k].subset;
    for (std::size_t i = 0; i < subsets.size(); ++i) {
      const auto& s = subsets[i];
      out << (k + 1) << ',';
      put(out, result.grid.centre[i].x);
      out << ',';
      put(out, result.grid.centre[i].y);
      out << ',';
      put(out, s.u);
      out << ',';
      put(out, s.v);
      out << ',';
      put(out, s.zncc);
      out << ',' << (s.is_valid() ? 1 : 0) << '\n';
    }
  }
}

void write_displacements_csv(const PivResult& result, const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw InputError("PIV: cannot write '" + file.string() + "'");
  write_displacements_csv(result, out);
  if (!out) throw InputError("PIV: writing '" + file.string() + "' failed");
}

}  // namespace trapdem
