#pragma once
// Each OpenMP thread owns a contiguous block of the particles (in cell order), in every loop
// that splits them: the same split everywhere, so that a particle's data stays with one thread.
#include <cstddef>

namespace trapdem {

struct ThreadBlock {
  std::size_t begin, end;  // particle indices [begin, end)
};

// Thread `thread`'s block of n particles among `threads`.
inline ThreadBlock thread_block(std::size_t n, int thread, int threads) {
  return {n * std::size_t(thread) / std::size_t(threads), n * std::size_t(thread + 1) / std::size_t(threads)};
}

}  // namespace trapdem
