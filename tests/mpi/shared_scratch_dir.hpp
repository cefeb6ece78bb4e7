#pragma once
// A scratch folder that the ranks of one communicator share (tests/scratch_dir.hpp for one
// process): rank 0 makes it (mkdtemp) and sends its path to the others, so it exists before any
// rank sees the path; rank 0 alone removes it, when its object goes. A test therefore declares it
// before its last collective call (the final MPI_Barrier), so that no rank still writes into it.
#include <mpi.h>

#include <filesystem>
#include <optional>
#include <string>

#include "../scratch_dir.hpp"

namespace trapdem::test {

class SharedScratchDir {
 public:
  // Collective over `comm`.
  explicit SharedScratchDir(const std::string& prefix, MPI_Comm comm = MPI_COMM_WORLD) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    std::string path;
    if (rank == 0) path = owned_.emplace(prefix).path().string();
    int length = static_cast<int>(path.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, comm);
    path.resize(static_cast<std::size_t>(length));
    MPI_Bcast(path.data(), length, MPI_CHAR, 0, comm);
    path_ = path;
  }

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }

 private:
  std::optional<ScratchDir> owned_;  // rank 0's
  std::filesystem::path path_;
};

}  // namespace trapdem::test
