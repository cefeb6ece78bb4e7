// Issue 14, "errors together": a configuration with several faults reports all of them at once,
// unknown keys first, then wrong values, then broken rules across keys; before, the first rule
// violation hid the rest (a file without pluviation.count hid its misspelt keys).
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "experiment/experiment_config.hpp"
#include "io/config.hpp"

namespace trapdem {
namespace {

std::string refusal(const std::string& text) {
  try {
    Config c = Config::parse(text, "bad.toml");
    ExperimentConfig::from(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigErrorsTogether, AFileWithoutAPourEndStillShowsItsUnknownKeys) {
  const std::string m = refusal("[box]\nwidht = 0.3\n[pluviaton]\ncount = 100\n");
  SCOPED_TRACE(m);
  const auto unknown = m.find("2 unknown keys");
  const auto typo = m.find("bad.toml:2:9: unknown key box.widht (did you mean box.width?)");
  const auto table = m.find("unknown key pluviaton.count");
  const auto rule = m.find("pluviation.count");
  ASSERT_NE(unknown, std::string::npos);
  ASSERT_NE(typo, std::string::npos);
  ASSERT_NE(table, std::string::npos);
  ASSERT_NE(m.find("a particle count or a fill_height"), std::string::npos);
  EXPECT_LT(typo, m.find("a particle count or a fill_height"));
  EXPECT_NE(rule, std::string::npos);
}

TEST(ConfigErrorsTogether, UnknownKeysThenWrongValuesThenRules) {
  const std::string m = refusal(
      "[trapdoor]\n"
      "width = 0.5\n"                // 2: a rule: wider than the box (0.325 m)
      "[box]\n"
      "height = \"tall\"\n"          // 4: a wrong type
      "colour = \"red\"\n"           // 5: unknown
      "[contact]\n"
      "restitution = 2.0\n"          // 7: out of range
      "[settling]\n"
      "min_time = 0.9\n"             // 9: a rule: above max_time (0.5 s)
      "[pluviation]\n"
      "count = 100\n");
  SCOPED_TRACE(m);
  const auto unknown = m.find("bad.toml:5:10: unknown key box.colour");
  const auto type = m.find("bad.toml:4:10: box.height = \"tall\" (a string)");
  const auto range = m.find("bad.toml:7:15: contact.restitution = 2.0 (a float): expected a number in (0, 1]");
  const auto door = m.find("bad.toml:2:9: trapdoor.width = 0.5 (a float): expected a trapdoor narrower than the box");
  const auto settle = m.find("bad.toml:9:12: settling.min_time = 0.9 (a float): expected at most max_time");
  for (auto at : {unknown, type, range, door, settle}) ASSERT_NE(at, std::string::npos);
  EXPECT_LT(unknown, type);
  EXPECT_LT(type, door);
  EXPECT_LT(range, door);
  EXPECT_LT(door, settle);
}

// A value that should be a table is one error, not one per key read below it.
TEST(ConfigErrorsTogether, AValueForATableIsReportedOnce) {
  const std::string m = refusal("box = 3\n[pluviation]\ncount = 100\n");
  SCOPED_TRACE(m);
  const auto first = m.find("box = 3 (an integer): expected a table");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(m.find("box = 3 (an integer): expected a table", first + 1), std::string::npos);
}

// Other readers of Config keep the first error (collect_errors() is the experiment's choice).
TEST(ConfigErrorsTogether, WithoutCollectingTheFirstErrorThrows) {
  Config c = Config::parse("a = \"x\"\n", "plain.toml");
  EXPECT_THROW(c.get_double("a", 1.0), InputError);
  EXPECT_THROW(c.fail("a", "something else"), InputError);
}

}  // namespace
}  // namespace trapdem
