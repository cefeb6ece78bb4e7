#include "experiment/run_identity.hpp"

#include <cstdint>
#include <map>

#include <fmt/format.h>

#include "experiment/experiment_config.hpp"
#include "io/config.hpp"

namespace trapdem {

std::string resolved_values(const Config& config) {
  const std::string text = config.resolved_toml();
  std::size_t start = 0;
  while (start < text.size() && text[start] == '#') {
    const std::size_t end = text.find('\n', start);
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return text.substr(start);
}

std::string config_digest(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis and prime (64 bit)
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

// Iterative: the depth is the document's.
std::map<std::string, std::string> value_leaves(std::string_view text, const char* name) {
  Config doc = Config::parse(text, name);
  std::map<std::string, std::string> out;
  std::vector<std::string> pending = {""};
  while (!pending.empty()) {
    const std::string table = pending.back();
    pending.pop_back();
    for (const std::string& leaf : doc.keys(table)) {
      const std::string key = table.empty() ? leaf : table + "." + leaf;
      if (key == "derived") continue;
      if (doc.is_table(key)) pending.push_back(key);
      else out[key] = doc.require_value_text(key);
    }
  }
  return out;
}

std::string as_read_now(std::string_view resolved, const char* name) {
  Config config = Config::parse(resolved, name);
  (void)ExperimentConfig::from(config);  // fills in the keys added since, and checks the rest
  return resolved_values(config);
}

std::vector<ConfigChange> config_changes(std::string_view started, std::string_view now) {
  const auto before = value_leaves(started, "the checkpoint's configuration");
  const auto after = value_leaves(now, "resolved.toml");
  std::vector<ConfigChange> changes;
  auto b = before.begin();
  auto a = after.begin();
  while (b != before.end() || a != after.end()) {
    if (a == after.end() || (b != before.end() && b->first < a->first)) {
      changes.push_back({b->first, b->second, "(absent)"});
      ++b;
    } else if (b == before.end() || a->first < b->first) {
      changes.push_back({a->first, "(absent)", a->second});
      ++a;
    } else {
      if (a->second != b->second) changes.push_back({a->first, b->second, a->second});
      ++a;
      ++b;
    }
  }
  return changes;
}

}  // namespace trapdem
