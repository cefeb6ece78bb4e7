// The typo suggestion behind "did you mean ...?" for unknown keys and commands.
#include <gtest/gtest.h>

#include "core/nearest_name.hpp"

namespace trapdem {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("analyze", "analyze"), 0u);
  EXPECT_EQ(edit_distance("anlyze", "analyze"), 1u);   // one deletion
  EXPECT_EQ(edit_distance("analyse", "analyze"), 1u);  // one substitution
  EXPECT_EQ(edit_distance("", "run"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // the textbook case
}

TEST(NearestName, ATypoFindsItsCommandAndNonsenseFindsNone) {
  const std::vector<std::string> commands = {"run", "analyze", "study", "calibrate"};
  EXPECT_EQ(nearest_name("anlyze", commands), "analyze");
  EXPECT_EQ(nearest_name("studdy", commands), "study");
  EXPECT_EQ(nearest_name("NOSUCH", commands), "");
  EXPECT_EQ(nearest_name("x", {}), "");
}

}  // namespace
}  // namespace trapdem
