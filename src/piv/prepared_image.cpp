#include "piv/prepared_image.hpp"

namespace trapdem {

PreparedImage prepare_image(const GreyImage& image) {
  PreparedImage p;
  image.intensity.convertTo(p.intensity32, CV_32F);
  p.spline = make_bspline_image(image.intensity);
  return p;
}

}  // namespace trapdem
