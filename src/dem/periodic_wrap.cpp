#include "dem/periodic_wrap.hpp"

#include <cmath>

namespace trapdem {

void wrap_periodic(Particles& p, const Domain& dom) {
  if (!dom.any_periodic()) return;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      if (!dom.periodic[a]) continue;
      const double len = dom.length(a);
      double& xa = p.position[i][a];
      const double shift = std::floor((xa - dom.lower[a]) / len);
      if (shift != 0.0) {
        xa -= shift * len;
        if (xa >= dom.upper[a]) xa = dom.lower[a];  // round-off at the upper bound
        p.image[i][a] += static_cast<std::int32_t>(shift);
      }
    }
  }
}

}  // namespace trapdem
