#pragma once
// Which of a study's runs one call runs (`trapdem study --case NAME --seed N`, trapdem.study(cases=,
// seeds=)): a workstation runs one case, or one packing of a replicate scale, of a study whose other
// runs run elsewhere or later, into the same folder. The study's report still covers every finished
// run. Empty lists select everything.
#include <cstdint>
#include <string>
#include <vector>

#include "study/study_definition.hpp"

namespace trapdem {

struct CaseRun;

struct RunSelection {
  std::vector<std::string> cases;    // case names (the study's [cases.NAME]); empty: every case
  std::vector<std::uint64_t> seeds;  // packing seeds (pluviation.seed of the run); empty: every seed

  bool everything() const { return cases.empty() && seeds.empty(); }
  bool selects(const std::string& case_name, std::uint64_t seed) const;
  // "cases rf3; seeds 2" (for the study's log).
  std::string describe() const;
};

// InputError naming what is wrong: a case the study does not have (its cases listed), or a seed
// that no selected case's runs pack with (their seeds listed). `runs` is checked_study_runs's.
void check_run_selection(const RunSelection& selection, const StudyDefinition& study,
                         const std::vector<std::vector<CaseRun>>& runs);

}  // namespace trapdem
