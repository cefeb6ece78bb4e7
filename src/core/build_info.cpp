#include "core/build_info.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace trapdem {

std::string describe_build(const BuildInfo& info) {
  if (info.commit.empty()) return "unknown (not built from a git checkout)";
  const std::string_view short_hash = info.commit.substr(0, 12);
  return info.modified ? fmt::format("{} with uncommitted changes", short_hash) : std::string(short_hash);
}

namespace {

// "key\t: value" -> value, for the first line of the first processor's block with that key.
std::string cpuinfo_value(std::string_view cpuinfo, std::string_view key) {
  std::size_t start = 0;
  while (start < cpuinfo.size()) {
    std::size_t end = cpuinfo.find('\n', start);
    if (end == std::string_view::npos) end = cpuinfo.size();
    const std::string_view line = cpuinfo.substr(start, end - start);
    if (line.empty()) break;  // the end of the first processor's block
    const std::size_t colon = line.find(':');
    if (colon != std::string_view::npos) {
      std::string_view name = line.substr(0, colon);
      while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.remove_suffix(1);
      if (name == key) {
        std::string_view value = line.substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        return std::string(value);
      }
    }
    start = end + 1;
  }
  return {};
}

bool has_flag(const std::string& flags, std::string_view flag) {
  std::istringstream words(flags);
  std::string word;
  while (words >> word)
    if (word == flag) return true;
  return false;
}

}  // namespace

std::string describe_cpu(std::string_view cpuinfo) {
  const std::string name = cpuinfo_value(cpuinfo, "model name");
  if (name.empty()) return "unknown processor";
  std::string text = name;
  const std::string family = cpuinfo_value(cpuinfo, "cpu family"), model = cpuinfo_value(cpuinfo, "model");
  // Virtual machines often name only the brand ("AMD EPYC"): the family and model tell Zen 3 (25/1)
  // from Zen 5 (26/2).
  if (!family.empty() && !model.empty()) text += fmt::format(" (family {}, model {})", family, model);
  const std::string flags = cpuinfo_value(cpuinfo, "flags");
  if (has_flag(flags, "avx512f"))
    text += ", AVX-512";
  else if (has_flag(flags, "avx2"))
    text += ", AVX2";
  return text;
}

std::string describe_cpu() {
  std::ifstream in("/proc/cpuinfo");
  if (!in) return "unknown processor";
  std::ostringstream text;
  text << in.rdbuf();
  return describe_cpu(text.str());
}

}  // namespace trapdem
