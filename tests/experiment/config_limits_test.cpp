// Issue 14, "values that are not finite or not sane": every float key of the experiment refuses
// inf and nan (the reader does it once for all, src/io/config.cpp), every key has an upper bound,
// and what the run derives from the keys (time step, step counts, particle count) is checked too,
// naming the key it comes from.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/thread_count.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/run_identity.hpp"
#include "io/config.hpp"

namespace trapdem {
namespace {

const std::string kTiny = std::string(TRAPDEM_SOURCE_DIR) + "/presets/tiny.toml";

// The message of the InputError that reading the tiny preset with `overrides` throws ("" if none).
std::string refusal(const std::vector<std::string>& overrides) {
  try {
    Config c = Config::load_file(kTiny);
    c.apply_overrides(overrides);
    ExperimentConfig::from(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The numeric leaves of the tiny preset's resolved record (every key the run reads), as
// {key, is_array}, except the output-only [derived] table and integers.
std::vector<std::pair<std::string, bool>> float_keys() {
  Config c = Config::load_file(kTiny);
  ExperimentConfig::from(c);
  std::vector<std::pair<std::string, bool>> out;
  for (const auto& [key, text] : value_leaves(c.resolved_toml(), "resolved.toml")) {
    const bool is_array = text.front() == '[';
    const bool is_float = text.find_first_of(".e") != std::string::npos && text.front() != '"';
    if (is_float) out.emplace_back(key, is_array);
  }
  return out;
}

TEST(ConfigLimits, EveryFloatKeyRefusesInfAndNan) {
  const auto keys = float_keys();
  ASSERT_GE(keys.size(), 30u) << "the walk over the resolved record found too few float keys";
  for (const auto& [key, is_array] : keys) {
    for (const char* bad : {"inf", "-inf", "nan"}) {
      const std::string value = is_array ? fmt::format("[{}]", bad) : bad;
      const std::string m = refusal({key + "=" + value});
      SCOPED_TRACE(key + "=" + value + " -> " + m);
      ASSERT_FALSE(m.empty()) << "accepted";
      EXPECT_NE(m.find(key), std::string::npos);
      EXPECT_NE(m.find("expected a finite number"), std::string::npos);
    }
  }
}

// 1e300 of anything is a unit slip: every float key has a bound, in its range or in a rule.
TEST(ConfigLimits, EveryFloatKeyHasAnUpperBound) {
  for (const auto& [key, is_array] : float_keys()) {
    const std::string value = is_array ? "[1e300]" : "1e300";
    const std::string m = refusal({key + "=" + value});
    SCOPED_TRACE(key + "=" + value + " -> " + m);
    ASSERT_FALSE(m.empty()) << "accepted";
    EXPECT_NE(m.find(key), std::string::npos);
  }
  for (const char* key : {"pluviation.count", "numerics.threads"}) {
    const std::string m = refusal({std::string(key) + "=1000000000000"});
    SCOPED_TRACE(m);
    EXPECT_NE(m.find(key), std::string::npos);
    EXPECT_NE(m.find("expected an integer in [0, "), std::string::npos);
  }
}

// A denormal stiffness passes "> 0" but gives sqrt(m/k) = inf: the derived step names the key.
TEST(ConfigLimits, DenormalStiffnessGivesNoInfiniteTimeStep) {
  std::string m = refusal({"contact.normal_stiffness=1e-320"});
  EXPECT_NE(m.find("contact.normal_stiffness"), std::string::npos) << m;
  EXPECT_NE(m.find("finite critical time step"), std::string::npos) << m;
  m = refusal({"numerics.time_step_fraction=1e-300"});
  EXPECT_NE(m.find("numerics.time_step_fraction"), std::string::npos) << m;
  EXPECT_NE(m.find("at least 1e-15 s"), std::string::npos) << m;
}

TEST(ConfigLimits, StepCountsAndParticleCountAreBounded) {
  std::string m = refusal({"trapdoor.rate=1e-9"});  // 0.004 m at 1e-9 m/s: 4e6 s, 2.6e12 steps
  EXPECT_NE(m.find("trapdoor.rate"), std::string::npos) << m;
  EXPECT_NE(m.find("time steps"), std::string::npos) << m;
  m = refusal({"contact.normal_stiffness=1e14", "settling.max_time=9000"});  // dt 1.6e-10 s: 5.8e13 steps
  EXPECT_NE(m.find("settling.max_time"), std::string::npos) << m;
  m = refusal({"box.width=9", "box.depth=9", "box.height=2", "pluviation.fill_height=2"});
  EXPECT_NE(m.find("pluviation.fill_height"), std::string::npos) << m;
  EXPECT_NE(m.find("particles"), std::string::npos) << m;
  m = refusal({"output.ground_reaction_step=1e-12"});
  EXPECT_NE(m.find("output.ground_reaction_step"), std::string::npos) << m;
  // The preset itself passes.
  EXPECT_EQ(refusal({}), "");
}

TEST(ThreadCount, ZeroToTheMaximumWithAClearMessage) {
  EXPECT_EQ(parse_thread_count("0", "--threads"), 0);
  EXPECT_EQ(parse_thread_count("4096", "--threads"), 4096);
  for (const char* bad : {"abc", "-1", "4097", "100000", "99999999999999999999999", "2.5", "", "+3"}) {
    try {
      parse_thread_count(bad, "--threads");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("expected 0 (all cores) or a thread count up to 4096"), std::string::npos) << m;
      EXPECT_LT(m.size(), 120u) << m;
    }
  }
  EXPECT_THROW(checked_thread_count(100000, "--threads"), InputError);
  // The library refuses it too, before the configuration is read.
  FolderRunOptions o;
  o.config_file = kTiny;
  o.out_dir = "/nonexistent/never-created";
  o.threads = 100000;
  EXPECT_THROW(run_in_folder(o), InputError);
}

}  // namespace
}  // namespace trapdem
