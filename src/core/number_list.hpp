#pragma once
// Comma-separated numbers given on the command line or in a small text file: "--roi 10,20,400,300",
// "--origin -162.5,360", a control point "512.0, 388.5, 0, 120".
#include <cstddef>
#include <string>
#include <vector>

namespace trapdem {

// Exactly `count` finite numbers separated by commas (blanks around each allowed). Throws
// InputError "<what> '<text>': ..." naming the item that is not a number, a non-finite one, or the
// count expected.
std::vector<double> parse_number_list(const std::string& text, std::size_t count, const std::string& what);

}  // namespace trapdem
