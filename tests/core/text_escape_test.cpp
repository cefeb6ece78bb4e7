// The escapes of core/text_escape.hpp: JSON/TOML quoted strings, XML/HTML markup and CSV fields (quoted is
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

TEST(TextEscape, CsvFieldQuotesOnlyWhatWouldBreakTheRow) {
  EXPECT_EQ(csv_field("RF1"), "RF1");
  EXPECT_EQ(csv_field("k_n 5e4 N/m"), "k_n 5e4 N/m");
  EXPECT_EQ(csv_field(""), "");
  // RFC 4180: a comma, quote or line break puts the field in quotes; its quotes are doubled.
  EXPECT_EQ(csv_field("all shortcuts, step fraction 0.4"), "\"all shortcuts, step fraction 0.4\"");
  EXPECT_EQ(csv_field("the \"fast\" rain"), "\"the \"\"fast\"\" rain\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
}
