#pragma once
// The parameters that differ between a study's cases, from their resolved configurations: what the
// report shows beside the results, so a reader sees what was varied (and what varied by accident).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace trapdem {

struct ParameterDifference {
  std::string key;                  // dotted, e.g. "contact.rolling_friction"
  std::vector<std::string> values;  // one per case, TOML text; "—" where a case lacks the key
};

// `configurations[c]` is case c's (key, value) list. Keys whose values are not all equal, in the order
// of their first appearance; `ignored` keys (the case name) are left out.
std::vector<ParameterDifference> differing_parameters(
    const std::vector<std::vector<std::pair<std::string, std::string>>>& configurations,
    const std::vector<std::string>& ignored = {"name", "description"});

// A run folder's resolved.toml flattened (derived values included).
std::vector<std::pair<std::string, std::string>> resolved_parameters(const std::filesystem::path& run_dir);

}  // namespace trapdem
