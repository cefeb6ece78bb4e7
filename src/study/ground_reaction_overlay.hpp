#pragma once
// `trapdem figure --grc DIR...`: the ground reaction curves of several run folders on one chart,
// outside a study. Each run's trapdoor.csv gives its trapdoor stress over its value before
// lowering against the trapdoor displacement over the trapdoor width (its resolved.toml gives B and
// the run's name); one curve per run, in the order given.
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem {

// The legend entries: `labels` where given (one per run, or none), else each run's name, followed
// by its folder's name where two runs share a name. Throws InputError if labels and runs differ in
// number.
std::vector<std::string> ground_reaction_legend(const std::vector<std::filesystem::path>& dirs,
                                                const std::vector<std::string>& names,
                                                const std::vector<std::string>& labels);

// Writes the chart to `out` (the extension picks the format). Throws InputError naming a folder
// without trapdoor.csv or resolved.toml, and the CSV reader's errors. Returns the legend entries.
std::vector<std::string> write_ground_reaction_overlay(const std::filesystem::path& out,
                                                       const std::vector<std::filesystem::path>& dirs,
                                                       const std::vector<std::string>& labels = {});

}  // namespace trapdem
