// What `trapdem piv` maps pixels to the model with: a control point file fitted affinely and
// projectively (--control-points, --fit), the --scale / --origin / --roi numbers, and the lengths and
// thread counts other commands take (--at, --grid, --threads). The first byte picks the reader.
#include <sstream>

#include "core/length_text.hpp"
#include "core/number_list.hpp"
#include "core/thread_count.hpp"
#include "fuzz_target.hpp"
#include "piv/control_point_file.hpp"
#include "piv/pixel_to_model.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(fuzzing::as_text(data + 1, size - 1));
  fuzzing::expecting_clear_errors([&] {
    switch (data[0] % 6) {
      case 0:
      case 1: {
        std::istringstream in(text);
        const auto points = parse_control_points(in, "points.csv");
        const auto fit = fit_control_points(points, data[0] % 6 == 0 ? ControlPointFitKind::affine
                                                                      : ControlPointFitKind::projective);
        for (const ControlPoint& p : points) to_model(fit.transform, p.pixel);
        break;
      }
      case 2: {
        const auto v = parse_number_list(text, 3, "--scale/--origin");  // mm per px, then X,Z of pixel (0,0)
        to_model(scale_transform(v[0], {-v[1] / v[0], v[2] / v[0]}), {1.0, 1.0});
        break;
      }
      case 3: parse_number_list(text, 4, "--roi"); break;
      case 4: parse_length_list(text, "--at"); parse_length(text, "--grid"); break;
      case 5: parse_thread_count(text, "--threads"); break;
    }
  });
  return 0;
}
