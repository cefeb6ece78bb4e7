// The analysis follows particles by id between snapshots (src/analysis/analysis_run.cpp, issue 41):
// an id that is not in every snapshot used is left out and named in the result's warnings (metrics
// .json `warnings`), never dropped silently; an id twice in one snapshot is refused.
#include <gtest/gtest.h>

#include <string>

#include "synthetic_points.hpp"
#include "analysis/analysis_run.hpp"
#include "core/errors.hpp"

using namespace trapdem;

namespace {

// A jittered lattice of 2 mm particles settling uniformly by delta / 2, ids 1000, 1001, ...
AnalysisFrame frame(const std::string& label, double delta) {
  static const auto nodes = test::jittered_hex_lattice(0.001, 0.099, 0.001, 0.06, 0.002, 0.2, 7);
  AnalysisFrame f{label, delta, {}};
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    f.snapshot.id.push_back(1000 + static_cast<std::int64_t>(k));
    f.snapshot.position.push_back({nodes[k].x, 0.009, nodes[k].z - 0.5 * delta});
    f.snapshot.radius.push_back(0.001);
  }
  return f;
}

const SpecimenGeometry kGeometry{"ids", 0.1, 0.01, 0.07, {0.05, 0.03, 0.0}};

}  // namespace

TEST(IdMatching, AllIdsMatchNoWarning) {
  const AnalysisResult r = analyze_frames({frame("000001", 0.0), frame("000004", 0.004)}, kGeometry, {});
  EXPECT_EQ(r.matched_particles, frame("x", 0.0).snapshot.size());
  EXPECT_TRUE(r.unmatched_ids.empty());
}

TEST(IdMatching, MissingAndUnknownIdsAreNamed) {
  const AnalysisFrame ref = frame("000001", 0.0);
  AnalysisFrame current = frame("000004", 0.004);
  // Particle 1003 gone from the current snapshot, and an id the reference does not know.
  current.snapshot.id[3] = 987654;
  const AnalysisResult r = analyze_frames({ref, current}, kGeometry, {});
  EXPECT_EQ(r.matched_particles, ref.snapshot.size() - 1);
  ASSERT_EQ(r.unmatched_ids.size(), 2u);
  EXPECT_EQ(r.unmatched_ids[0],
            "1 particle of the reference 000001 is missing from 000004 (id 1003): left out of the analysis");
  EXPECT_EQ(r.unmatched_ids[1],
            "1 particle of 000004 is not in the reference 000001 (id 987654): left out of the analysis");
}

TEST(IdMatching, ManyMissingIdsListTheFirstFive) {
  const AnalysisFrame ref = frame("000001", 0.0);
  AnalysisFrame current = frame("000004", 0.004);
  for (std::size_t k = 0; k < 7; ++k) {  // the first seven particles gone
    current.snapshot.id.erase(current.snapshot.id.begin());
    current.snapshot.position.erase(current.snapshot.position.begin());
    current.snapshot.radius.erase(current.snapshot.radius.begin());
  }
  const AnalysisResult r = analyze_frames({ref, current}, kGeometry, {});
  ASSERT_EQ(r.unmatched_ids.size(), 1u);
  EXPECT_EQ(r.unmatched_ids[0], "7 particles of the reference 000001 are missing from 000004 "
                                "(id 1000, 1001, 1002, 1003, 1004, ...): left out of the analysis");
}

TEST(IdMatching, AnIdTwiceInOneSnapshotIsRefused) {
  AnalysisFrame current = frame("000004", 0.004);
  current.snapshot.id[10] = current.snapshot.id[2];
  try {
    analyze_frames({frame("000001", 0.0), current}, kGeometry, {});
    FAIL() << "a duplicated id was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("000004: particle id 1002 appears twice (particles 2 and 10)"),
              std::string::npos)
        << e.what();
  }
}
