// The code and host a run names (src/core/build_info.hpp): the processor as /proc/cpuinfo gives it
// on the hosts we have run on (a VM that names only the brand, an Intel Xeon), the build's commit.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "core/build_info.hpp"

using namespace trapdem;

namespace {

// The first processor's block of a 2-core Firecracker guest on a Zen 5 host (trimmed), then the
// second's: only the first is read.
const char* const kZen5Guest =
    "processor\t: 0\n"
    "vendor_id\t: AuthenticAMD\n"
    "cpu family\t: 26\n"
    "model\t\t: 2\n"
    "model name\t: AMD EPYC\n"
    "flags\t\t: fpu vme sse2 avx avx2 avx512f avx512dq\n"
    "\n"
    "processor\t: 1\n"
    "model name\t: something else\n";

const char* const kXeon =
    "processor\t: 0\n"
    "vendor_id\t: GenuineIntel\n"
    "cpu family\t: 6\n"
    "model\t\t: 143\n"
    "model name\t: Intel(R) Xeon(R) Platinum 8481C CPU @ 2.70GHz\n"
    "flags\t\t: fpu sse2 avx avx2\n";

}  // namespace

TEST(BuildInfo, TheCpuIsNamedWithItsFamilyModelAndWidestVectors) {
  EXPECT_EQ(describe_cpu(kZen5Guest), "AMD EPYC (family 26, model 2), AVX-512");
  EXPECT_EQ(describe_cpu(kXeon), "Intel(R) Xeon(R) Platinum 8481C CPU @ 2.70GHz (family 6, model 143), AVX2");
  // "model name" is not "model": the family/model pair is read from the exact keys.
  EXPECT_EQ(describe_cpu("model name\t: Some CPU\nflags\t: sse2\n"), "Some CPU");
  EXPECT_EQ(describe_cpu(""), "unknown processor");
  EXPECT_EQ(describe_cpu("processor\t: 0\nvendor_id\t: AuthenticAMD\n"), "unknown processor");
  // This host's own: whatever it is, named and not empty.
  EXPECT_FALSE(describe_cpu().empty());
}

TEST(BuildInfo, TheBuildIsNamedByItsShortCommitAndSaysWhenItWasModified) {
  const std::string hash = "7a62e4e1c2d3f4a5b6c7d8e9f0a1b2c3d4e5f6a7";
  EXPECT_EQ(describe_build(BuildInfo{hash, false}), "7a62e4e1c2d3");
  EXPECT_EQ(describe_build(BuildInfo{hash, true}), "7a62e4e1c2d3 with uncommitted changes");
  EXPECT_EQ(describe_build(BuildInfo{"", false}), "unknown (not built from a git checkout)");
  // This build's: a full hash (the tests build from a git checkout or an unpacked archive).
  const std::string commit(build_info().commit);
  EXPECT_TRUE(commit.empty() || std::regex_match(commit, std::regex("[0-9a-f]{40}"))) << commit;
}
