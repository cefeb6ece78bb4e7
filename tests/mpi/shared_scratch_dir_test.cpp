// The ranks' shared scratch folder (shared_scratch_dir.hpp): one folder, the same path on every
// rank, there when a rank gets its path, and gone once the object has gone on rank 0 (kept under
// TRAPDEM_KEEP_SCRATCH=1).
#include "shared_scratch_dir.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpi_support.hpp"

namespace fs = std::filesystem;

namespace trapdem {
namespace {

using testing_support::world_rank;
using testing_support::world_size;

TEST(SharedScratchDir, OneFolderForEveryRankRemovedByRankZero) {
  ASSERT_GE(world_size(), 2) << "run on several ranks";
  std::string path;
  {
    const test::SharedScratchDir dir("trapdem-mpi-shared");
    path = dir.path().string();
    EXPECT_TRUE(fs::is_directory(dir.path())) << "rank " << world_rank();
    EXPECT_EQ(dir.path().filename().string().rfind("trapdem-mpi-shared-", 0), 0u) << dir.path();
    std::ofstream(dir / ("rank-" + std::to_string(world_rank()))) << "x";
    // Every rank got rank 0's path.
    std::vector<char> zero(path.begin(), path.end());
    zero.resize(4096, '\0');
    MPI_Bcast(zero.data(), static_cast<int>(zero.size()), MPI_CHAR, 0, MPI_COMM_WORLD);
    EXPECT_EQ(std::string(zero.data()), path);
    MPI_Barrier(MPI_COMM_WORLD);
    if (world_rank() == 0) {
      for (int r = 0; r < world_size(); ++r) EXPECT_TRUE(fs::exists(dir / ("rank-" + std::to_string(r)))) << r;
    }
    MPI_Barrier(MPI_COMM_WORLD);
  }
  MPI_Barrier(MPI_COMM_WORLD);  // rank 0 has removed it, or kept it as asked
  if (test::ScratchDir::keep_requested()) {
    EXPECT_TRUE(fs::exists(path)) << "rank " << world_rank();
    MPI_Barrier(MPI_COMM_WORLD);
    if (world_rank() == 0) fs::remove_all(path);
  } else {
    EXPECT_FALSE(fs::exists(path)) << "rank " << world_rank();
  }
}

}  // namespace
}  // namespace trapdem
