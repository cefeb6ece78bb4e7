#pragma once
// OpenMP thread counts asked for by a user (--threads, numerics.threads): 0 means all cores, and a
// count is bounded. libgomp creates every thread asked for: 20 000 hung and 100 000 crashed in it
// (issue 14), long before any machine has that many cores.
#include <string>
#include <string_view>

namespace trapdem {

// The largest thread count accepted.
inline constexpr int kMaxThreads = 4096;

// What a thread option expects, for messages: "0 (all cores) or a thread count up to 4096".
std::string thread_count_expectation();

// The count in `text` (decimal digits only), or InputError "<what> '<text>': expected 0 (all cores)
// or a thread count up to 4096" for anything else (letters, a sign, a fraction, too many digits).
int parse_thread_count(std::string_view text, std::string_view what);

// `count` itself, or the same InputError if it is negative or above kMaxThreads.
int checked_thread_count(long long count, std::string_view what);

}  // namespace trapdem
