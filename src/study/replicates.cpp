#include "study/replicates.hpp"

#include <fmt/format.h>

#include "io/config.hpp"

namespace trapdem {

ReplicateRequest read_replicate_request(Config& document, const std::string& table) {
  const std::string prefix = table.empty() ? "" : table + ".";
  ReplicateRequest r;
  const std::string count_key = prefix + "replicates", seeds_key = prefix + "seeds";
  const bool has_count = document.has(count_key), has_seeds = document.has(seeds_key);
  if (has_count) r.count = document.require_int(count_key, Range::closed(1.0, double(kMaxReplicates)));
  if (has_seeds) {
    const std::vector<std::int64_t> seeds =
        document.require_vector<std::int64_t>(seeds_key, "", Range::closed(0.0, double(kMaxSeed)));
    if (seeds.empty()) throw document.error(seeds_key, "at least one packing seed (integers >= 0)");
    if (seeds.size() > std::size_t(kMaxReplicates))
      throw document.error(seeds_key, fmt::format("at most {} seeds (one whole run each), not {}", kMaxReplicates,
                                                  seeds.size()));
    for (std::size_t k = 0; k < seeds.size(); ++k)
      for (std::size_t j = 0; j < k; ++j)
        if (seeds[j] == seeds[k])
          throw document.error(seeds_key, fmt::format("distinct seeds ({} is given twice: replicates with the same "
                                                      "seed are the same run)", seeds[k]));
    if (has_count && static_cast<std::int64_t>(seeds.size()) != r.count)
      throw document.error(seeds_key, fmt::format("as many seeds as {} says ({}), not {}", count_key, r.count,
                                                  seeds.size()));
    for (std::int64_t s : seeds) r.seeds.push_back(static_cast<std::uint64_t>(s));
    r.count = static_cast<std::int64_t>(seeds.size());
  }
  return r;
}

const ReplicateRequest& applicable_request(const ReplicateRequest& study_case, const ReplicateRequest& scale,
                                           const ReplicateRequest& study) {
  if (study_case.asked()) return study_case;
  if (scale.asked()) return scale;
  return study;
}

std::vector<std::uint64_t> replicate_seeds(const ReplicateRequest& request, std::uint64_t case_seed) {
  if (!request.asked()) return {case_seed};
  if (!request.seeds.empty()) return request.seeds;
  std::vector<std::uint64_t> seeds;
  for (std::int64_t k = 0; k < request.count; ++k) seeds.push_back(case_seed + static_cast<std::uint64_t>(k));
  return seeds;
}

std::string replicate_folder_name(std::uint64_t seed) { return fmt::format("seed-{}", seed); }

}  // namespace trapdem
