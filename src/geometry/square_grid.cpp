#include "membra/geometry/square_grid.hpp"

#include <algorithm>
#include <cmath>

namespace membra {

std::pair<int, int> square_grid(double w, double h, int n) {
  const double ratio = std::max(w, h) / std::min(w, h);
  int best = n;
  // From 51 nodes on, rounding the cells along the longer side is always within 1 %.
  for (int k = n; k <= std::max(n, 51); ++k) {
    const double cells = std::max(1.0, std::round((k - 1) * ratio));
    if (std::abs(cells / ((k - 1) * ratio) - 1.0) <= 0.01) {
      best = k;
      break;
    }
  }
  const int along = static_cast<int>(std::max(1.0, std::round((best - 1) * ratio))) + 1;
  return w <= h ? std::pair{best, along} : std::pair{along, best};
}

}  // namespace membra
