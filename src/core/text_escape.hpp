#pragma once
// Text escaped for the formats trapdem writes: quoted strings of JSON and TOML, XML/HTML content
// and attribute values (the XDMF index of snapshots, the study report's page), and CSV fields.
#include <string>
#include <string_view>

namespace trapdem {

// `text` in double quotes with the escapes JSON and TOML basic strings share (\" \\ \n \t \r \b
// \f, other control characters as \u00XX).
std::string quoted(std::string_view text);

// `text` for XML or HTML element content and attribute values: & < > " ' as &amp; &lt; &gt; &quot;
// &#39; (the numeric reference for ', which both XML and every HTML version read).
std::string markup_escape(std::string_view text);

// A text field of a CSV row (RFC 4180): as it is, or, when it holds a comma, a double quote or a
// line break, in double quotes with each of its quotes doubled. A study case's label is free text
// ("all shortcuts, step fraction 0.4"): unquoted, its comma would shift every later column.
std::string csv_field(std::string_view text);

}  // namespace trapdem
