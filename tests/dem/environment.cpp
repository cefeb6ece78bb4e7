// The analytic tests run the engine on one OpenMP thread: they are serial-sized (a handful of
// particles), and on a shared or single-core machine OpenMP's barriers would cost far more than
// the work. threads_test.cpp sets the thread count it needs and restores this default.
#include <gtest/gtest.h>
#include <omp.h>

namespace {
struct OneThread : ::testing::Environment {
  void SetUp() override { omp_set_num_threads(1); }
};
[[maybe_unused]] ::testing::Environment* const kOneThread = ::testing::AddGlobalTestEnvironment(new OneThread);
}  // namespace
