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
