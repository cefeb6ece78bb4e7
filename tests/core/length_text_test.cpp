// Lengths on the command line (core/length_text.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "core/errors.hpp"
#include "core/length_text.hpp"

using namespace trapdem;

TEST(LengthText, ParsesUnitsAndRejectsNonsense) {
  EXPECT_DOUBLE_EQ(parse_length("80mm", "--at"), 0.08);
  EXPECT_DOUBLE_EQ(parse_length("10 mm", "--at"), 0.01);
  EXPECT_DOUBLE_EQ(parse_length("0.08", "--at"), 0.08);
  EXPECT_DOUBLE_EQ(parse_length("8cm", "--at"), 0.08);
  EXPECT_DOUBLE_EQ(parse_length(" 1e-3 m ", "--at"), 0.001);
  EXPECT_THROW(parse_length("80 furlongs", "--at"), InputError);
  EXPECT_THROW(parse_length("mm", "--at"), InputError);
  EXPECT_THROW(parse_length("", "--at"), InputError);
  EXPECT_EQ(parse_length_list("0mm, 10 mm,0.02", "--displacements"), (std::vector<double>{0.0, 0.01, 0.02}));
}
