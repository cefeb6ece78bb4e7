// The engine's serial-sized tests (tests/dem: a handful of particles; tests/io: a few hundred) run
// on one OpenMP thread: on a shared or 2-core machine OpenMP's barriers would cost far more than
// the work. The checkpoint's bitwise promise holds for any fixed thread count, and
// tests/dem/threads_test.cpp sets the thread count it needs and restores this default. Linked into
// the test programs named in tests/CMakeLists.txt (one_thread_modules).
#include <gtest/gtest.h>
#include <omp.h>

namespace {
struct OneThread : ::testing::Environment {
  void SetUp() override { omp_set_num_threads(1); }
};
[[maybe_unused]] ::testing::Environment* const kOneThread = ::testing::AddGlobalTestEnvironment(new OneThread);
}  // namespace
