// Issue 14, "readers that recurse": a configuration nested 50 000 tables deep crashed inside
// toml++ (it recurses), and the unused-key walk recursed too. The depth is bounded by a scan of the
// text before parsing; the walk is iterative. The JSON reader (run.json, metrics.json) bounds its
// recursion as well.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "io/config.hpp"

namespace trapdem {
namespace {

std::string refusal(const std::string& text) {
  try {
    Config c = Config::parse(text, "deep.toml");
    c.report_unused();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string dotted(int levels) {
  std::string key = "a";
  for (int i = 1; i < levels; ++i) key += ".a";
  return key;
}

TEST(ConfigNesting, DeepHeadersKeysAndValuesAreRefusedBeforeParsing) {
  for (const std::string& text : {"x = 1\n[" + dotted(50000) + "]\ny = 1\n",   // a header
                                  "x = 1\n" + dotted(50000) + " = 1\n",          // a dotted key
                                  std::string("[") + dotted(40) + "]\n" + dotted(40) + " = 1\n",  // both, 80 deep
                                  "x = 1\nv = " + std::string(5000, '[') + std::string(5000, ']') + "\n",
                                  "x = 1\nv = " + [] {
                                    std::string t;
                                    for (int i = 0; i < 5000; ++i) t += "{a = ";
                                    return t + "1" + std::string(5000, '}');
                                  }() + "\n"}) {
    const std::string m = refusal(text);
    SCOPED_TRACE(m.substr(0, 200));
    EXPECT_NE(m.find("deep.toml:2:"), std::string::npos);
    EXPECT_NE(m.find("nested"), std::string::npos);
    EXPECT_NE(m.find("expected at most 64"), std::string::npos);
  }
}

// What is not nesting is not counted: dots in strings, comments and numbers, long flat arrays.
TEST(ConfigNesting, ShallowDocumentsPass) {
  std::string flat = "values = [";
  for (int i = 0; i < 2000; ++i) flat += "1.5, ";
  flat += "2.5]\n";
  const std::string text = "name = \"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c\"\n"
                           "# " + dotted(100) + "\n" +
                           "'quoted.key.with.dots' = 1\n"
                           "[" + dotted(30) + "]\n" + dotted(30) + " = {b = [[1.0, 2.0], [3.0]], c = 'x.y'}\n" + flat +
                           "ml = \"\"\"\n[" + dotted(100) + "]\n\"\"\"\n";
  Config c = Config::parse(text, "flat.toml");
  EXPECT_EQ(c.unused_keys().size(), 6u);
  // An override's key and value are bounded the same way.
  Config d = Config::parse("x = 1\n", "d.toml");
  EXPECT_THROW(d.apply_override(dotted(100) + "=1"), InputError);
  d.apply_override("y=" + std::string(500, '[') + std::string(500, ']'));  // taken as a string, not parsed
}

// The unused-key walk holds its own stack: 60 levels (under the bound) of unknown tables are listed.
TEST(ConfigNesting, UnusedKeyWalkListsDeepKeys) {
  Config c = Config::parse(std::string("[") + dotted(60) + "]\nleaf = 1\n[b]\nc = 2\n", "deep.toml");
  const auto unused = c.unused_keys();
  ASSERT_EQ(unused.size(), 2u);
  EXPECT_EQ(unused[0], dotted(60) + ".leaf");
  EXPECT_EQ(unused[1], "b.c");
}

TEST(JsonNesting, DeepDocumentsAreRefusedShallowOnesRead) {
  for (const std::string& text : {std::string(100000, '[') + std::string(100000, ']'),
                                  [] {
                                    std::string t;
                                    for (int i = 0; i < 100000; ++i) t += "{\"a\":";
                                    return t + "1" + std::string(100000, '}');
                                  }()}) {
    try {
      Json::parse(text, "deep.json");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("nested deeper than 256"), std::string::npos) << e.what();
    }
  }
  const Json ok = Json::parse(std::string(200, '[') + "1" + std::string(200, ']'), "ok.json");
  EXPECT_EQ(ok.type(), Json::Type::array);
}

}  // namespace
}  // namespace trapdem
