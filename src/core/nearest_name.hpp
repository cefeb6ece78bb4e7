#pragma once
// The known name closest to a mistyped one (Levenshtein distance): "did you mean ...?" for
// configuration keys (io/config.cpp) and command names (apps/main.cpp).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// Insertions, deletions and substitutions that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is within a typo's reach (at most max(2, |name| / 3)
// edits), else "".
std::string nearest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace trapdem
