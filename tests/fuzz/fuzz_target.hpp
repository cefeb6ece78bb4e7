#pragma once
// What every fuzz target shares (tests/fuzz, `make fuzz`): our documented errors are the expected
// answer to bad input, so they end a run quietly; anything else escapes to libFuzzer, which reports
// it as a finding (an uncaught exception aborts), as it does a crash, a sanitizer report, a hang
// (-timeout) or too much memory (-rss_limit_mb, -malloc_limit_mb).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "../io/io_test_support.hpp"

namespace trapdem::fuzzing {

template <class F>
void expecting_clear_errors(F&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const FileError&) {
  } catch (const SimulationError&) {
  }
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The input cut at NUL bytes: the first part and the rest (e.g. a document and its --set lines).
inline std::vector<std::string> split_at_nul(std::string_view text) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == '\0') parts.emplace_back();
    else parts.back() += c;
  }
  return parts;
}

// A file holding the input, for readers whose entry point takes a path; one per process, rewritten
// for every input, in a folder of its own (the file name `name` keeps its extension).
inline std::filesystem::path input_file(std::string_view bytes, const std::string& name) {
  static const io_testing::ScratchDir dir("trapdem-fuzz");  // removed at the process's exit
  const auto path = dir / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

}  // namespace trapdem::fuzzing
