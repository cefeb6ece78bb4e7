#pragma once
// Lengths given on the command line: "80mm", "80 mm", "8cm", "0.08m" or a bare number in metres
// ("0.08"). Used for trapdoor displacements (--at, --reference), grid spacings and depths.
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

// The length in metres. Throws InputError naming `what` (e.g. "--at") and the text if it is not
// a number with an optional unit among m, cm, mm, um.
double parse_length(std::string_view text, std::string_view what);

// Splits "0mm, 10 mm,0.02" at commas and parses each as a length (blank items skipped).
std::vector<double> parse_length_list(std::string_view text, std::string_view what);

// "80 mm", "0.5 mm", "12.25 mm": a length in mm for messages and titles (up to 2 decimals, no
// trailing zeros).
std::string format_mm(double metres);

}  // namespace trapdem
