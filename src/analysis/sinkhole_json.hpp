#pragma once
// The sinkhole estimates (analysis/sinkhole.hpp) as JSON: `trapdem sinkhole --json`.
#include "analysis/sinkhole.hpp"
#include "core/json.hpp"

namespace trapdem {

Json to_json(const SuppositionEstimate& e);
Json to_json(const MechanismComparison& c);

}  // namespace trapdem
