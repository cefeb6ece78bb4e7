// The strict configuration dictionary: typed look-ups with defaults, errors that name
// file:line, key, what was found and what was expected; unknown keys; overrides; resolved output.
#include "io/config.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "io_test_support.hpp"

using namespace trapdem;
using namespace trapdem::io_testing;

namespace {

// The message of the InputError that `action` throws ("" if none).
template <class F>
std::string error_of(F&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const char* kRun = R"(# a trapdoor run
[box]
width = 0.325
depth = 0.0182
height = 0.36
[material]
density = 2500
restitution = 0.9
sizes = [0.0019, 0.002, 0.0021]
model = "elastic_plastic"
[output]
snapshots_mm = [0, 5, 10]
)";

}  // namespace

TEST(Config, TypedLookUpsWithDefaults) {
  Config c = Config::parse(kRun, "run.toml");
  EXPECT_EQ(c.get_double("box.width", 1.0, "m", Range::positive()), 0.325);
  EXPECT_EQ(c.get_double("material.density", 0.0, "kg/m^3"), 2500.0);  // an integer is a valid float
  EXPECT_EQ(c.get_double("box.travel", 0.08, "m"), 0.08);               // absent: the default
  EXPECT_EQ(c.get_int("output.every", 100), 100);
  EXPECT_TRUE(c.get_bool("output.xdmf", true));
  EXPECT_EQ(c.get_string("material.model", "none"), "elastic_plastic");
  EXPECT_EQ(c.get_vector<double>("material.sizes", {}), (std::vector<double>{0.0019, 0.002, 0.0021}));
  EXPECT_EQ(c.get_vector<std::int64_t>("output.snapshots_mm", {}), (std::vector<std::int64_t>{0, 5, 10}));
  Config box = c.get_table("box");
  EXPECT_EQ(box.get_double("depth", 0.0, "m"), 0.0182);
  EXPECT_EQ(box.require_double("height", "m", Range::positive()), 0.36);
  EXPECT_EQ(c.get_table("material").get_double("restitution", 0.5, "", Range::unit_open_closed()), 0.9);
  EXPECT_TRUE(c.has("box.width"));
  EXPECT_FALSE(c.has("box.nothing"));
  EXPECT_EQ(c.keys("box"), (std::vector<std::string>{"width", "depth", "height"}));  // as the file writes them
  c.apply_override("box.angle=0.5");  // an override's new key has no place in the file: it goes last
  EXPECT_EQ(c.keys("box"), (std::vector<std::string>{"width", "depth", "height", "angle"}));
  c.get_double("box.angle", 0.0);
  EXPECT_NO_THROW(c.report_unused());
}

TEST(Config, UnknownKeysAreListedWithFileLineAndASuggestion) {
  ScratchDir dir;
  const auto path = dir / "run.toml";
  std::ofstream(path) << "[box]\nwidth = 0.3\nwidht = 0.4\n\n[extra]\nfoo = 1\n";
  Config c = Config::load_file(path.string());
  c.get_double("box.width", 0.3, "m");
  const std::string message = error_of([&] { c.report_unused(); });
  EXPECT_TRUE(contains(message, path.string() + ":3:")) << message;
  EXPECT_TRUE(contains(message, "unknown key box.widht")) << message;
  EXPECT_TRUE(contains(message, "did you mean box.width?")) << message;
  EXPECT_TRUE(contains(message, path.string() + ":6:")) << message;
  EXPECT_TRUE(contains(message, "unknown key extra.foo")) << message;
  EXPECT_TRUE(contains(message, "2 unknown keys")) << message;
  EXPECT_EQ(c.unused_keys(), (std::vector<std::string>{"box.widht", "extra.foo"}));
}

TEST(Config, WrongTypeNamesFileLineKeyFoundAndExpected) {
  Config c = Config::parse("[box]\nwidth = \"wide\"\ncount = 2.5\nflag = 1\n", "bad.toml");
  const std::string m = error_of([&] { c.get_double("box.width", 0.3, "m", Range::positive()); });
  EXPECT_TRUE(contains(m, "bad.toml:2:")) << m;
  EXPECT_TRUE(contains(m, "box.width = \"wide\" (a string)")) << m;
  EXPECT_TRUE(contains(m, "expected a number > 0 (m)")) << m;
  const std::string n = error_of([&] { c.get_int("box.count", 1); });
  EXPECT_TRUE(contains(n, "bad.toml:3:")) << n;
  EXPECT_TRUE(contains(n, "box.count = 2.5 (a float): expected an integer")) << n;
  const std::string b = error_of([&] { c.get_bool("box.flag", false); });
  EXPECT_TRUE(contains(b, "box.flag = 1 (an integer): expected a boolean")) << b;
  const std::string t = error_of([&] { c.get_double("box.width.inner", 0.0); });
  EXPECT_TRUE(contains(t, "box.width") && contains(t, "expected a table")) << t;
}

TEST(Config, OutOfRangeValuesAreErrors) {
  Config c = Config::parse("radius = -0.001\nrestitution = 1.5\nzero_e = 0.0\nsizes = [0.001, -0.002]\n", "r.toml");
  const std::string r = error_of([&] { c.get_double("radius", 0.001, "m", Range::positive()); });
  EXPECT_TRUE(contains(r, "r.toml:1:")) << r;
  EXPECT_TRUE(contains(r, "radius = -0.001 (a float): expected a number > 0 (m)")) << r;
  const std::string e = error_of([&] { c.get_double("restitution", 0.9, "", Range::unit_open_closed()); });
  EXPECT_TRUE(contains(e, "r.toml:2:") && contains(e, "expected a number in (0, 1]")) << e;
  EXPECT_FALSE(error_of([&] { c.get_double("zero_e", 0.9, "", Range::unit_open_closed()); }).empty());
  const std::string v = error_of([&] { c.get_vector<double>("sizes", {}, "m", Range::positive()); });
  EXPECT_TRUE(contains(v, "r.toml:4:") && contains(v, "sizes[1] = -0.002")) << v;
  const std::string i = error_of([&] { Config::parse("n = -3", "i.toml").get_int("n", 1, Range::at_least(1)); });
  EXPECT_TRUE(contains(i, "n = -3 (an integer): expected an integer >= 1")) << i;
}

TEST(Config, ChoicesRequiredKeysAndCrossKeyRules) {
  Config c = Config::parse("[trapdoor]\nwidth = 0.4\nmodel = \"spring\"\n[box]\nwidth = 0.325\n", "t.toml");
  const std::string m = error_of([&] { c.get_choice("trapdoor.model", "linear", {"linear", "hertz"}); });
  EXPECT_TRUE(contains(m, "t.toml:3:") && contains(m, "expected one of \"linear\", \"hertz\"")) << m;
  const std::string missing = error_of([&] { c.require_double("box.height", "m", Range::positive()); });
  EXPECT_TRUE(contains(missing, "t.toml: missing required key box.height: expected a number > 0 (m)")) << missing;
  const double box = c.get_double("box.width", 0.3, "m");
  const double door = c.get_double("trapdoor.width", 0.05, "m");
  ASSERT_GT(door, box);
  const std::string rule = c.error("trapdoor.width", "at most the box width (0.325 m)").what();
  EXPECT_TRUE(contains(rule, "t.toml:2:") && contains(rule, "trapdoor.width = 0.4 (a float): expected at most")) << rule;
  Config defaults = Config::parse("", "d.toml");
  defaults.get_double("dt", 2e-6, "s");
  const std::string d = defaults.error("dt", "below the critical step").what();
  EXPECT_TRUE(contains(d, "dt = 2e-06 (a float) (the default)")) << d;
}

TEST(Config, SyntaxErrorsNameFileLineAndColumn) {
  const std::string m = error_of([] { Config::parse("[box]\nwidth = = 3\n", "syntax.toml"); });
  EXPECT_TRUE(contains(m, "syntax.toml:2:") && contains(m, "TOML syntax error")) << m;
  const std::string f = error_of([] { Config::load_file("/nonexistent/run.toml"); });
  EXPECT_TRUE(contains(f, "/nonexistent/run.toml")) << f;
}

TEST(Config, OverridesApplyOnTopOfTheFile) {
  Config c = Config::parse(kRun, "run.toml");
  c.apply_overrides({"box.width=0.5", "material.sizes = [0.001, 0.002]", "stage.name=lowering",
                     "stage.gravity=\"50 g\"", "output.xdmf=false", "trapdoor.travel=8e-2"});
  EXPECT_EQ(c.get_double("box.width", 0.0, "m"), 0.5);
  EXPECT_EQ(c.get_vector<double>("material.sizes", {}), (std::vector<double>{0.001, 0.002}));
  EXPECT_EQ(c.get_string("stage.name", ""), "lowering");     // bare word: a string
  EXPECT_EQ(c.get_string("stage.gravity", ""), "50 g");
  EXPECT_FALSE(c.get_bool("output.xdmf", true));
  EXPECT_EQ(c.get_double("trapdoor.travel", 0.0, "m"), 0.08);
  // An override's bad value is blamed on the override, not on a file line.
  c.apply_override("material.restitution=2");
  const std::string e = error_of([&] { c.get_double("material.restitution", 0.9, "", Range::unit_open_closed()); });
  EXPECT_TRUE(contains(e, "--set material.restitution=2: material.restitution = 2 (an integer)")) << e;
  // A misspelt override is an unknown key like any other.
  c.apply_override("box.widht=1");
  const std::string u = error_of([&] { c.report_unused(); });
  EXPECT_TRUE(contains(u, "--set box.widht=1: unknown key box.widht")) << u;
  // Malformed assignments and a value where a table is.
  EXPECT_FALSE(error_of([&] { c.apply_override("box.width"); }).empty());
  EXPECT_FALSE(error_of([&] { c.apply_override("box..width=1"); }).empty());
  EXPECT_TRUE(contains(error_of([&] { c.apply_override("box.width.x=1"); }), "box.width is a float"));
  EXPECT_TRUE(contains(error_of([&] { c.apply_override("box=1"); }), "box is a table"));
}

TEST(Config, ResolvedOutputRoundTrips) {
  Config c = Config::parse(kRun, "run.toml");
  const double width = c.get_double("box.width", 0.0, "m");
  c.get_double("box.depth", 0.0, "m");
  c.get_double("box.height", 0.0, "m");
  const double third = c.get_double("box.third", 1.0 / 3.0, "m");
  const double tiny = c.get_double("contact.overlap", 1.23456789012345e-300);
  const std::int64_t n = c.get_int("count", 300000);
  const bool periodic = c.get_bool("box.periodic_depth", false);
  const std::string label = c.get_string("label", "quote \" backslash \\ tab \t new\nline");
  const std::vector<double> sizes = c.get_vector<double>("material.sizes", {});
  const std::vector<std::string> stages = c.get_vector<std::string>("stages", {"pluviation", "settling"});
  c.get_table("material").get_double("density", 0.0, "kg/m^3");
  c.get_table("material").get_double("restitution", 0.0);
  c.get_string("material.model", "");
  c.get_vector<std::int64_t>("output.snapshots_mm", {});
  c.add_derived("derived.time_step", 1.0e-6 / 7.0, "s");
  c.add_derived("derived.particle_count", std::int64_t{299873});
  c.add_derived("derived.note", "from box and material");
  c.report_unused();
  const std::string text = c.resolved_toml();
  EXPECT_TRUE(contains(text, "width = 0.325  # m")) << text;
  EXPECT_TRUE(contains(text, "[derived]")) << text;

  Config back = Config::parse(text, "resolved.toml");
  EXPECT_EQ(back.get_double("box.width", 0.0), width);
  EXPECT_EQ(back.get_double("box.depth", 0.0), 0.0182);
  EXPECT_EQ(back.get_double("box.height", 0.0), 0.36);
  EXPECT_EQ(back.get_double("box.third", 0.0), third);  // bitwise: shortest round-trip formatting
  EXPECT_EQ(back.get_double("contact.overlap", 0.0), tiny);
  EXPECT_EQ(back.get_int("count", 0), n);
  EXPECT_EQ(back.get_bool("box.periodic_depth", true), periodic);
  EXPECT_EQ(back.get_string("label", ""), label);
  EXPECT_EQ(back.get_vector<double>("material.sizes", {}), sizes);
  EXPECT_EQ(back.get_vector<std::string>("stages", {}), stages);
  EXPECT_EQ(back.get_double("material.density", 0.0), 2500.0);
  EXPECT_EQ(back.get_double("material.restitution", 0.0), 0.9);
  EXPECT_EQ(back.get_string("material.model", ""), "elastic_plastic");
  EXPECT_EQ(back.get_vector<std::int64_t>("output.snapshots_mm", {}), (std::vector<std::int64_t>{0, 5, 10}));
  EXPECT_EQ(back.get_double("derived.time_step", 0.0), 1.0e-6 / 7.0);
  EXPECT_EQ(back.get_int("derived.particle_count", 0), 299873);
  EXPECT_EQ(back.get_string("derived.note", ""), "from box and material");
  EXPECT_NO_THROW(back.report_unused());  // nothing in it but what was read

  // Run again from the resolved file: its [derived] table is not an unknown key.
  Config again = Config::parse(text, "resolved.toml");
  again.get_double("box.width", 0.0);
  const std::vector<std::string> unread = again.unused_keys();
  EXPECT_EQ(unread.size(), 13u);  // the 14 input keys but box.width; no derived.*
  EXPECT_EQ(std::count(unread.begin(), unread.end(), "derived.time_step"), 0);
}
