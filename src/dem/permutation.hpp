#pragma once
// Reordering an array of per-item values (particles, bodies) by a permutation given as
// new_to_old: the item now at k was at new_to_old[k].
#include <cstddef>
#include <cstdint>
#include <vector>

namespace trapdem {

template <class T>
void apply_permutation(std::vector<T>& values, const std::vector<std::uint32_t>& new_to_old) {
  std::vector<T> out(values.size());
  const std::size_t n = new_to_old.size();
  // A gather: each k writes its own element (the same result on any number of threads).
#pragma omp parallel for schedule(static) if (n > 8192)
  for (std::size_t k = 0; k < n; ++k) out[k] = values[new_to_old[k]];
  values.swap(out);
}

}  // namespace trapdem
