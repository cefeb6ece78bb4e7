#pragma once
// Text escaped for the formats trapdem writes: quoted strings of JSON and TOML, and XML/HTML
// content and attribute values (the XDMF index of snapshots, the study report's page).
#include <string>
#include <string_view>

namespace trapdem {

// `text` in double quotes with the escapes JSON and TOML basic strings share (\" \\ \n \t \r \b
// \f, other control characters as \u00XX).
std::string quoted(std::string_view text);

// `text` for XML or HTML element content and attribute values: & < > " ' as &amp; &lt; &gt; &quot;
// &#39; (the numeric reference for ', which both XML and every HTML version read).
std::string markup_escape(std::string_view text);

}  // namespace trapdem
