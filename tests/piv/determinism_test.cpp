// The result does not depend on the number of OpenMP threads: the parallel stages treat every
// subset alone and the reliability-guided propagation is sequential.
#include <gtest/gtest.h>

#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"

namespace trapdem {
namespace {

TEST(PivDeterminism, SameResultOnOneAndTwoThreads) {
  SpeckleSettings s;
  s.width = 160;
  s.height = 128;
  s.noise_std = 2.0;
  std::vector<DisplacementField> fields;
  for (int k = 1; k <= 4; ++k) fields.push_back(scaled(simple_shear(0.03, {80.0, 64.0}), k));
  const auto images = synthesize_speckle_sequence(s, fields);
  PivSettings one, two;
  one.threads = 1;
  two.threads = 2;
  const PivResult a = run_piv(images, one), b = run_piv(images, two);
  ASSERT_EQ(a.image_count(), b.image_count());
  EXPECT_EQ(a.reference_images, b.reference_images);
  for (std::size_t k = 0; k < a.image_count(); ++k)
    for (std::size_t i = 0; i < a.grid.size(); ++i) {
      const auto &x = a.image[k].subset[i], &y = b.image[k].subset[i];
      EXPECT_EQ(x.status, y.status);
      if (std::isfinite(x.u) || std::isfinite(y.u)) {
        EXPECT_EQ(x.u, y.u);  // bitwise
        EXPECT_EQ(x.v, y.v);
        EXPECT_EQ(x.zncc, y.zncc);
      }
    }
}

}  // namespace
}  // namespace trapdem
