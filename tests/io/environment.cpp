// The io tests run the engine on one OpenMP thread: their simulations are a few hundred particles,
// and on a shared 2-core machine OpenMP's barriers would cost more than the work. The checkpoint's
// bitwise promise holds for any fixed thread count (tests/dem/threads_test.cpp covers the engine).
#include <gtest/gtest.h>
#include <omp.h>

namespace {
struct OneThread : ::testing::Environment {
  void SetUp() override { omp_set_num_threads(1); }
};
[[maybe_unused]] ::testing::Environment* const kOneThread = ::testing::AddGlobalTestEnvironment(new OneThread);
}  // namespace
