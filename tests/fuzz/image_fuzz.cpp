// The PIV image loader (read_grey_image: OpenCV's decoders, then the grey conversion) given a
// damaged or hostile file. OpenCV is not instrumented: coverage guides only our code.
#include "fuzz_target.hpp"
#include "piv/grey_image.hpp"

using namespace trapdem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzzing::input_file(fuzzing::as_text(data, size), "image.png");
  fuzzing::expecting_clear_errors([&] {
    if (is_readable_image(file)) read_grey_image(file);
  });
  return 0;
}
