// The cost of a run's output at paper scale: K snapshots of N particles appended to snapshots.h5
// the way a run does (io/snapshot.hpp: each append rewrites the whole file atomically), and the
// checkpoint-sized read back. Prints one line per append: seconds and the file's size.
//
// Usage: output [--particles N] [--snapshots K] [--dir DIR]   (defaults 300000, 10, /tmp)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include "io/snapshot.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  long n = 300000, k_max = 10;
  fs::path dir = fs::temp_directory_path();
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a];
    if (key == "--particles") n = std::atol(argv[a + 1]);
    else if (key == "--snapshots") k_max = std::atol(argv[a + 1]);
    else if (key == "--dir") dir = argv[a + 1];
    else {
      std::fprintf(stderr, "usage: %s [--particles N] [--snapshots K] [--dir DIR]\n", argv[0]);
      return 2;
    }
  }
  if (n < 1 || k_max < 1) {
    std::fprintf(stderr, "output: N and K must be >= 1\n");
    return 2;
  }
  Particles p;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 0.3);
  for (long i = 0; i < n; ++i) p.add(i + 1, {u(rng), u(rng) * 0.06, u(rng)}, 0.001, 2500.0, {u(rng), u(rng), u(rng)});
  const fs::path h5 = dir / "trapdem_bench_output" / "snapshots.h5";
  fs::remove_all(h5.parent_path());
  fs::create_directories(h5.parent_path());
  double total = 0.0;
  for (long k = 0; k < k_max; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    append_snapshot(h5, make_snapshot(p, 0.1 * double(k), "lowering", 0.001 * double(k), k));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    total += s;
    std::printf("append %ld: %.2f s, file %.1f MB\n", k + 1, s, double(fs::file_size(h5)) / 1e6);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const Snapshot back = read_snapshot(h5, list_snapshots(h5).back().name);
  const double read_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("output N=%ld K=%ld appends_total_s=%.2f read_last_s=%.2f (%zu particles)\n", n, k_max, total, read_s,
              back.size());
  fs::remove_all(h5.parent_path());
  return 0;
}
