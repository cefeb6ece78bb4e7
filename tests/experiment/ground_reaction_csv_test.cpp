// Issue 41: trapdoor.csv as its readers take it (the study's summaries, `trapdem figure --grc`): a
// NaN or infinite cell, which trapdem never writes, is refused naming the line and column instead
// of drawing a silent gap (tests/study/figure_grc_empty_test.cpp: a file with its header only).
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "experiment/ground_reaction.hpp"

namespace trapdem {
namespace {

std::string with_row(const std::string& row) {
  return ground_reaction_csv({}) + "0.1,0,5,1000,1000,1,8,900,1,8,900,1\n" + row + "\n";
}

TEST(GroundReactionCsv, NonFiniteCellIsRefusedNamingLineAndColumn) {
  EXPECT_EQ(parse_ground_reaction_csv(with_row("0.2,0.001,4,800,1000,0.8,8,900,1,8,900,1"), "t.csv").size(), 2u);
  for (const char* bad : {"nan", "inf", "-inf"}) {
    try {
      parse_ground_reaction_csv(with_row(std::string("0.2,0.001,4,") + bad + ",1000,0.8,8,900,1,8,900,1"), "t.csv");
      ADD_FAILURE() << bad << " was read";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("t.csv:3: column 4"), std::string::npos) << m;
      EXPECT_NE(m.find("expected a finite number"), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace trapdem
