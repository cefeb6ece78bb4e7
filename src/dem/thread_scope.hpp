#pragma once
// The OpenMP thread count of one run, restored when the run ends (however it ends): a library call
// (a run, an element test, from the command line or Python) sets the threads it was asked for
// without leaving them set for the next call in the same process.
#include <omp.h>

namespace trapdem {

class ThreadScope {
 public:
  // `threads` > 0: that many threads until this goes; 0: the count as it is.
  explicit ThreadScope(int threads) : before_(omp_get_max_threads()) {
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~ThreadScope() { omp_set_num_threads(before_); }
  ThreadScope(const ThreadScope&) = delete;
  ThreadScope& operator=(const ThreadScope&) = delete;

 private:
  int before_;
};

}  // namespace trapdem
