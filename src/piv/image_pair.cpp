#include "piv/image_pair.hpp"

#include <limits>
#include <queue>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <utility>

#include "piv/integer_search.hpp"

namespace trapdem {

namespace {

// OpenMP threads for a requested count (0: OpenMP's default).
int thread_count(int requested) {
#ifdef _OPENMP
  return requested > 0 ? requested : omp_get_max_threads();
#else
  return 1;
#endif
}

// Converged beats not converged; then the higher ZNCC.
bool better(const IcgnResult& a, const IcgnResult& b) {
  const bool ca = a.outcome == IcgnOutcome::converged, cb = b.outcome == IcgnOutcome::converged;
  if (ca != cb) return ca;
  return a.zncc > b.zncc;
}

void keep_better(PairSolution& s, const IcgnResult& r) {
  if (!s.attempted || better(r, s.best)) s.best = r;
  s.attempted = true;
}

bool is_seed_candidate(const SubsetGrid& grid, std::size_t i, int spacing) {
  const int sp = spacing > 0 ? spacing : 1;
  // Offset by half a spacing so that a small grid still has a candidate near its middle.
  return (grid.column_of(i) + sp / 2) % sp == 0 && (grid.row_of(i) + sp / 2) % sp == 0;
}

}  // namespace

namespace {
IcgnResult refine(const ReferenceSubsets& refs, std::size_t i, const PreparedImage& reference,
                  const PreparedImage& current, const WarpParameters& start, const IcgnSettings& settings) {
  const auto subset = make_reference_subset(reference.spline, refs.centre[i], refs.subset_size);
  return refine_subset(*subset, current.spline, start, settings);  // present: the subset exists
}
}  // namespace

bool is_accepted(const PairSolution& s, bool textured, double min_valid_zncc) {
  return textured && s.attempted && s.best.outcome == IcgnOutcome::converged && s.best.zncc >= min_valid_zncc;
}

ReferenceSubsets make_reference_subsets(const PreparedImage& reference, const std::vector<cv::Point2d>& centres,
                                        const std::vector<bool>& alive, int subset_size,
                                        const TextureCriteria& criteria, int threads) {
  const std::size_t n = centres.size();
  ReferenceSubsets out;
  out.subset_size = subset_size;
  out.centre = centres;
  out.intensity_std.assign(n, std::numeric_limits<double>::quiet_NaN());
  out.sum_squared_gradient.assign(n, std::numeric_limits<double>::quiet_NaN());
  std::vector<char> present(n, 0), textured(n, 0);
#pragma omp parallel for schedule(dynamic, 64) num_threads(thread_count(threads))
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(n); ++i) {
    if (!alive[i]) continue;
    const auto s = make_reference_subset(reference.spline, centres[i], subset_size);
    if (!s) continue;
    present[i] = 1;
    textured[i] = has_enough_texture(*s, criteria);
    out.intensity_std[i] = s->intensity_std;
    out.sum_squared_gradient[i] = sum_squared_gradient(*s);
  }
  out.present.assign(present.begin(), present.end());
  out.textured.assign(textured.begin(), textured.end());
  return out;
}

std::vector<PairSolution> solve_image_pair(const SubsetGrid& grid, const ReferenceSubsets& refs,
                                           const PreparedImage& reference, const PreparedImage& current,
                                           const std::vector<std::optional<WarpParameters>>& start,
                                           const std::vector<cv::Point2d>& prediction, const PivSettings& settings) {
  const std::size_t n = grid.size();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(n);
  const int threads = thread_count(settings.threads);
  std::vector<PairSolution> solution(n);
  auto accepted = [&](std::size_t i) { return is_accepted(solution[i], refs.textured[i], settings.min_valid_zncc); };

  // 1. From the given starts, every subset alone. A start far from the truth can converge to a
  //    wrong local minimum with a middling ZNCC, so only results at or above the leapfrog
  //    threshold are kept; the others are found again by seeds and propagation.
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    if (!refs.present[i] || !start[i]) continue;
    const IcgnResult r = refine(refs, i, reference, current, *start[i], settings.icgn);
    const bool trusted = r.outcome == IcgnOutcome::converged && r.zncc >= settings.reference_update_zncc;
    if (trusted || r.outcome == IcgnOutcome::left_image) keep_better(solution[i], r);
  }

  // 2. Seeds: integer-pixel ZNCC search, then IC-GN, for candidates not yet accepted.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    if (!refs.textured[i] || accepted(i) || !is_seed_candidate(grid, i, settings.seed_spacing))
      continue;
    const IntegerMatch match = integer_pixel_search(reference.intensity32, current.intensity32, refs.centre[i],
                                                    grid.subset_size, prediction[i], settings.search_radius);
    if (!match.found || match.zncc < settings.min_valid_zncc) continue;  // no credible match in the window
    WarpParameters p;
    p.u = match.du;
    p.v = match.dv;
    keep_better(solution[i], refine(refs, i, reference, current, p, settings.icgn));
  }

  // 3. Reliability-guided propagation from every accepted subset, highest ZNCC first.
  using Entry = std::pair<double, std::ptrdiff_t>;  // (ZNCC, -index): ties go to the lower index
  std::priority_queue<Entry> queue;
  for (std::size_t i = 0; i < n; ++i)
    if (accepted(i)) queue.emplace(solution[i].best.zncc, -static_cast<std::ptrdiff_t>(i));
  std::vector<bool> propagated(n, false);
  while (!queue.empty()) {
    const std::size_t i = static_cast<std::size_t>(-queue.top().second);
    queue.pop();
    if (propagated[i]) continue;
    propagated[i] = true;
    for (std::size_t j : grid_neighbours(grid, i)) {
      if (!refs.present[j] || accepted(j)) continue;
      const cv::Point2d offset = refs.centre[j] - refs.centre[i];
      const WarpParameters guess = shifted_warp(solution[i].best.p, offset.x, offset.y);
      keep_better(solution[j], refine(refs, j, reference, current, guess, settings.icgn));
      if (accepted(j)) queue.emplace(solution[j].best.zncc, -static_cast<std::ptrdiff_t>(j));
    }
  }
  return solution;
}

}  // namespace trapdem
