#pragma once
namespace trapdem::app {
struct ShowcaseOptions {
  int particles = 6000;
  int threads = 0;  // 0: OpenMP's default
};
int run_showcase(const ShowcaseOptions& options);
}  // namespace trapdem::app
