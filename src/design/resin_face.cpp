#include "membra/design/resin_face.hpp"

#include <algorithm>
#include <cmath>

#include "membra/design/target_correspondence.hpp"

namespace membra {

int convex_face(const TargetSurface& target, const Box2& frame, const Vec2& p, double step) {
  const Vec2 lo = target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = target.x.topRows<2>().rowwise().maxCoeff();
  // Frame -> footprint, axis by axis, centre on centre.
  const Vec2 scale = (hi - lo).cwiseQuotient(frame.max - frame.min);
  const Vec2 h = step * scale;
  // The samples stay on the footprint (beyond it the target's height is its nearest vertex's,
  // flat, which would bend a rim's second difference): near the rim the Laplacian is taken a
  // step inwards.
  const Vec2 c = 0.5 * (lo + hi);
  Vec2 q = c + (p - 0.5 * (frame.min + frame.max)).cwiseProduct(scale);
  if (target.disk) {
    const double room = 0.5 * (hi - lo).minCoeff() - h.maxCoeff();
    if ((q - c).norm() > room) q = c + (q - c) * (std::max(room, 0.0) / (q - c).norm());
  } else {
    q = q.cwiseMax(lo + h).cwiseMin(hi - h);
  }
  const auto z = [&](double dx, double dy) { return target_height(target, q + Vec2(dx, dy)); };
  const double z0 = z(0.0, 0.0);
  const double laplacian = (z(h.x(), 0.0) + z(-h.x(), 0.0) - 2.0 * z0) / (h.x() * h.x()) +
                           (z(0.0, h.y()) + z(0.0, -h.y()) - 2.0 * z0) / (h.y() * h.y());
  // A dome (laplacian < 0) is convex seen from above: its coat goes on top.
  const double extent = (hi - lo).maxCoeff();
  return laplacian > 1e-9 / extent ? -1 : +1;
}

}  // namespace membra
