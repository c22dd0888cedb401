#include "membra/geometry/grid_prolongation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace membra {
namespace {

// The coarse particle nearest to the continuous grid position (u, v), by grid distance.
int nearest_particle(const GridSheet& g, double u, double v) {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const double d2 = (i - u) * (i - u) + (j - v) * (j - v);
    if (d2 < best_d2) best_d2 = d2, best = p;
  }
  return best;
}

}  // namespace

Points prolongate(const GridSheet& coarse, const Points& coarse_x, const GridSheet& fine) {
  if (coarse.num_particles() == 0 || coarse_x.cols() != coarse.num_particles())
    throw std::invalid_argument("prolongate: one coarse position per coarse particle");
  const double tol = 1e-9 * std::max(fine.width(), fine.height());
  if (std::abs(coarse.width() - fine.width()) > tol ||
      std::abs(coarse.height() - fine.height()) > tol)
    throw std::invalid_argument("prolongate: the two grids cover different sheets");
  Points x(3, fine.num_particles());
  for (int p = 0; p < fine.num_particles(); ++p) {
    const Vec2 paper = fine.position(fine.node(p).first, fine.node(p).second);
    // Continuous coarse grid coordinates of the fine node, and the cell that holds it.
    const double u = paper.x() / coarse.hx(), v = paper.y() / coarse.hy();
    const int i = std::clamp(static_cast<int>(std::floor(u)), 0, coarse.nx() - 2);
    const int j = std::clamp(static_cast<int>(std::floor(v)), 0, coarse.ny() - 2);
    const double fu = std::clamp(u - i, 0.0, 1.0), fv = std::clamp(v - j, 0.0, 1.0);
    Vec3 sum = Vec3::Zero();
    double weight = 0.0;
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) {
        const int q = coarse.particle(i + di, j + dj);
        const double w = (di ? fu : 1.0 - fu) * (dj ? fv : 1.0 - fv);
        if (q < 0 || w <= 0.0) continue;
        sum += w * coarse_x.col(q);
        weight += w;
      }
    x.col(p) =
        weight > 0.0 ? Vec3(sum / weight) : Vec3(coarse_x.col(nearest_particle(coarse, u, v)));
  }
  return x;
}

}  // namespace membra
