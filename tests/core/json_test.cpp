// The JSON value of core/json.hpp: written and parsed back.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.hpp"
#include "core/json.hpp"

using namespace trapdem;

TEST(Json, RoundTripsMetricsWithNullForNaN) {
  Json j = Json::object();
  j.set("a", 1.5);
  j.set("nan", std::nan(""));
  Json arr = Json::array();
  arr.push_back(1);
  arr.push_back("x\"y");
  j.set("list", arr);
  const Json back = Json::parse(j.dump());
  EXPECT_DOUBLE_EQ(back["a"].as_number(), 1.5);
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_EQ(back["list"][1].as_string(), "x\"y");
  EXPECT_THROW(Json::parse("{\"a\": }"), InputError);
}

namespace {
std::string parse_error(std::string_view text) {
  try {
    Json::parse(text, "f.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

// Found by tests/fuzz/json_fuzz.cpp: "[{" read the character past the end (a key expected at the
// end of the text); "\uZZZZ" was taken as the character 0 and "\u12zz" as U+0012 without a word.
TEST(Json, TextEndingWhereAKeyOrEscapeIsExpectedIsAnError) {
  EXPECT_EQ(parse_error("[{"), "f.json: offset 2: expected a string");
  EXPECT_EQ(parse_error("{\"a\": 1,"), "f.json: offset 8: expected a string");
  EXPECT_EQ(parse_error("\"\\uZZZZ\""), "f.json: offset 3: expected four hex digits after \\u");
  EXPECT_EQ(parse_error("\"\\u12zz\""), "f.json: offset 3: expected four hex digits after \\u");
  EXPECT_EQ(Json::parse("\"\\u0041\"").as_string(), "A");
}
