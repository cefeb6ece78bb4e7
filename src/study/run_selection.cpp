#include "study/run_selection.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "study/study_runner.hpp"

namespace trapdem {

bool RunSelection::selects(const std::string& case_name, std::uint64_t seed) const {
  const bool case_chosen = cases.empty() || std::find(cases.begin(), cases.end(), case_name) != cases.end();
  const bool seed_chosen = seeds.empty() || std::find(seeds.begin(), seeds.end(), seed) != seeds.end();
  return case_chosen && seed_chosen;
}

std::string RunSelection::describe() const {
  std::vector<std::string> parts;
  if (!cases.empty()) parts.push_back(fmt::format("cases {}", fmt::join(cases, ", ")));
  if (!seeds.empty()) parts.push_back(fmt::format("seeds {}", fmt::join(seeds, ", ")));
  return parts.empty() ? "every run" : fmt::format("{}", fmt::join(parts, "; "));
}

void check_run_selection(const RunSelection& selection, const StudyDefinition& study,
                         const std::vector<std::vector<CaseRun>>& runs) {
  std::vector<std::string> names;
  for (const StudyCase& c : study.cases) names.push_back(c.name);
  for (const std::string& name : selection.cases)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw InputError(fmt::format("--case {}: study '{}' has no such case (its cases: {})", name, study.name,
                                   fmt::join(names, ", ")));
  std::vector<std::uint64_t> seeds;  // what the selected cases' runs pack with
  for (std::size_t k = 0; k < study.cases.size(); ++k)
    if (selection.cases.empty() || std::find(selection.cases.begin(), selection.cases.end(), study.cases[k].name) !=
                                       selection.cases.end())
      for (const CaseRun& r : runs[k])
        if (std::find(seeds.begin(), seeds.end(), r.seed) == seeds.end()) seeds.push_back(r.seed);
  std::sort(seeds.begin(), seeds.end());
  for (const std::uint64_t seed : selection.seeds)
    if (std::find(seeds.begin(), seeds.end(), seed) == seeds.end())
      throw InputError(fmt::format("--seed {}: no run of {} packs with it (their packing seeds: {})", seed,
                                   selection.cases.empty() ? fmt::format("study '{}'", study.name)
                                                           : fmt::format("case {}", fmt::join(selection.cases, ", ")),
                                   fmt::join(seeds, ", ")));
}

}  // namespace trapdem
