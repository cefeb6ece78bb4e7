#pragma once
// Whether the error a rank is handling was agreed on by every rank (SlabDecomposition's and
// MpiRunRanks' agreements throw the same error on all ranks): then every rank stops by itself;
// an error seen by one rank alone must abort the others (mpi_run.cpp), or they would wait in
// their next exchange for ever.
#include <atomic>

namespace trapdem {

inline std::atomic<bool>& agreed_failure_flag() {
  static std::atomic<bool> flag{false};
  return flag;
}
inline void note_agreed_failure() { agreed_failure_flag() = true; }
inline bool failure_was_agreed() { return agreed_failure_flag(); }

}  // namespace trapdem
