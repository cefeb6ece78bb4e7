// The escapes of core/text_escape.hpp: JSON/TOML quoted strings and XML/HTML markup (quoted is
// qualified: for a std::string argument, argument-dependent lookup would also find std::quoted).
#include <gtest/gtest.h>

#include "core/text_escape.hpp"

using namespace trapdem;

TEST(TextEscape, QuotedEscapesWhatJsonAndTomlRequire) {
  EXPECT_EQ(trapdem::quoted("plain"), "\"plain\"");
  EXPECT_EQ(trapdem::quoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(trapdem::quoted("tab\tnew\nline\r"), "\"tab\\tnew\\nline\\r\"");
  EXPECT_EQ(trapdem::quoted(std::string("\x01", 1)), "\"\\u0001\"");
  EXPECT_EQ(trapdem::quoted("µm"), "\"µm\"");  // UTF-8 passes through
}

TEST(TextEscape, MarkupEscapesTheFiveSpecialCharacters) {
  EXPECT_EQ(markup_escape("White & Bolton <2004> \"shear\" it's"),
            "White &amp; Bolton &lt;2004&gt; &quot;shear&quot; it&#39;s");
  EXPECT_EQ(markup_escape("snapshots.h5"), "snapshots.h5");
  EXPECT_EQ(markup_escape(""), "");
}
