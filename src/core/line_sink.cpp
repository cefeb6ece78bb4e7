#include "core/line_sink.hpp"

#include <cstdio>

#include <fmt/format.h>

namespace trapdem {

void LineSink::say(const std::string& line) const {
  if (out) {
    out(line);
    return;
  }
  fmt::print("{}\n", line);
  std::fflush(stdout);
}

void LineSink::warn(const std::string& line) const {
  if (err) {
    err(line);
    return;
  }
  fmt::print(stderr, "{}\n", line);
}

}  // namespace trapdem
