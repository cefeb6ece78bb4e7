#pragma once
// The known name nearest a mistyped one, for "did you mean ...?" in the messages that refuse an
// unknown configuration key or command.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions
// that turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest `typed` by edit distance, if that distance is a typo's (at most
// max(2, typed.size() / 3)); "" when none is that close. Ties go to the first candidate.
std::string nearest_name(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace trapdem
