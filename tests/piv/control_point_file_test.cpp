// The control point file of `trapdem piv --control-points` (piv/control_point_file.hpp): points,
// comments and header lines, and the errors naming the line.
#include <gtest/gtest.h>

#include <sstream>

#include "core/errors.hpp"
#include "core/number_list.hpp"
#include "piv/control_point_file.hpp"

using namespace trapdem;

namespace {
std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_control_points(in, "points.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(ControlPointFile, PointsCommentsAndHeader) {
  std::istringstream in("x_px, y_px, x_mm, z_mm\r\n# the four corners\n\n100, 900, 0, 0\r\n-1.5,.5,2e1,3\n");
  const auto points = parse_control_points(in, "points.csv");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].pixel, cv::Point2d(100, 900));
  EXPECT_EQ(points[1].pixel, cv::Point2d(-1.5, 0.5));
  EXPECT_EQ(points[1].model, cv::Point2d(20, 3));
}

// A non-finite coordinate was taken and gave a NaN fit (issue 14: refuse non-finite input).
TEST(ControlPointFile, NonNumbersAndNonFiniteNumbersNameTheLine) {
  EXPECT_EQ(error_of("1, 2, 3, nan\n"), "points.csv:1 '1, 2, 3, nan': ' nan' is not a finite number");
  EXPECT_EQ(error_of("# c\n1, 2, inf, 4\n"), "points.csv:2 '1, 2, inf, 4': ' inf' is not a finite number");
  EXPECT_EQ(error_of("1, 2, 3\n"), "points.csv:1 '1, 2, 3': expected 4 numbers separated by commas");
  EXPECT_EQ(error_of("1, 2, 3, 4x\n"), "points.csv:1 '1, 2, 3, 4x': ' 4x' is not a number");
  EXPECT_THROW(parse_number_list("1e999,0", 2, "--origin"), InputError);
}
