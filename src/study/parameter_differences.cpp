#include "study/parameter_differences.hpp"

#include <algorithm>
#include <map>

#include "experiment/run_folder.hpp"
#include "io/config.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

std::vector<ParameterDifference> differing_parameters(
    const std::vector<std::vector<std::pair<std::string, std::string>>>& configurations,
    const std::vector<std::string>& ignored) {
  std::vector<std::string> order;
  std::vector<std::map<std::string, std::string>> lookup(configurations.size());
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    for (const auto& [key, value] : configurations[c]) {
      if (std::find(ignored.begin(), ignored.end(), key) != ignored.end()) continue;
      if (std::none_of(lookup.begin(), lookup.end(), [&key = key](const auto& m) { return m.count(key); }))
        order.push_back(key);
      lookup[c][key] = value;
    }
  }
  std::vector<ParameterDifference> out;
  for (const std::string& key : order) {
    ParameterDifference d;
    d.key = key;
    for (const auto& m : lookup) {
      const auto it = m.find(key);
      d.values.push_back(it == m.end() ? "—" : it->second);
    }
    if (std::adjacent_find(d.values.begin(), d.values.end(), std::not_equal_to<>()) != d.values.end())
      out.push_back(std::move(d));
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> resolved_parameters(const std::filesystem::path& run_dir) {
  Config resolved = Config::load_file(RunFolder(run_dir).resolved_toml().string());
  return flatten_values(resolved, "");
}

}  // namespace trapdem
