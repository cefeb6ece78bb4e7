#include "core/thread_count.hpp"

#include <charconv>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

std::string thread_count_expectation() { return fmt::format("0 (all cores) or a thread count up to {}", kMaxThreads); }

int parse_thread_count(std::string_view text, std::string_view what) {
  long long count = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), count);
  const bool digits_only = !text.empty() && text.front() != '-' && text.front() != '+';
  if (!digits_only || ec != std::errc() || end != text.data() + text.size() || count < 0 || count > kMaxThreads)
    throw InputError(fmt::format("{} '{}': expected {}", what, text, thread_count_expectation()));
  return static_cast<int>(count);
}

int checked_thread_count(long long count, std::string_view what) {
  if (count < 0 || count > kMaxThreads)
    throw InputError(fmt::format("{} {}: expected {}", what, count, thread_count_expectation()));
  return static_cast<int>(count);
}

}  // namespace trapdem
