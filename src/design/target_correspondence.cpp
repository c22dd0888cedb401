#include "membra/design/target_correspondence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace membra {
namespace {

// The sheet's centre and the scale from frame to footprint.
struct Placement {
  Vec2 centre;
  double scale;
};
Placement placement(const TargetSurface& target, const Points& frame_x) {
  const Vec3 lo = frame_x.rowwise().minCoeff(), hi = frame_x.rowwise().maxCoeff();
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  return {0.5 * (lo + hi).head<2>(), target.diameter / extent};
}

}  // namespace

double target_height(const TargetSurface& target, const Vec2& p) {
  const Points& x = target.x;
  for (const Triangle& t : target.triangles) {
    const Vec2 a = x.col(t[0]).head<2>(), b = x.col(t[1]).head<2>(), c = x.col(t[2]).head<2>();
    const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (std::abs(det) <= 0.0) continue;
    const Vec2 d = p - a;
    const double u = (d.x() * (c - a).y() - d.y() * (c - a).x()) / det;
    const double v = ((b - a).x() * d.y() - (b - a).y() * d.x()) / det;
    constexpr double eps = 1e-9;
    if (u < -eps || v < -eps || u + v > 1.0 + eps) continue;
    return (1.0 - u - v) * x(2, t[0]) + u * x(2, t[1]) + v * x(2, t[2]);
  }
  Eigen::Index nearest = 0;
  (x.topRows<2>().colwise() - p).colwise().squaredNorm().minCoeff(&nearest);
  return x(2, nearest);
}

Correspondence target_correspondence(const TargetSurface& target, const Points& frame_x,
                                     const Eigen::VectorXd& weights) {
  const Placement pl = placement(target, frame_x);
  Correspondence c{Points(3, frame_x.cols()), weights};
  for (Eigen::Index i = 0; i < frame_x.cols(); ++i) {
    const Vec2 u = pl.scale * (frame_x.col(i).head<2>() - pl.centre);
    c.target.col(i) = Vec3(u.x(), u.y(), target_height(target, u));
  }
  return c;
}

MetricStart metric_start(const TargetSurface& target, const Points& frame_x,
                         const DensityField& field, const Vec2& lambda) {
  const Placement pl = placement(target, frame_x);
  MetricStart m;
  m.density.resize(field.value.size());
  m.asks_min = std::numeric_limits<double>::infinity();
  m.asks_max = -m.asks_min;
  const double h = 0.25 * field.cell_size().minCoeff() * pl.scale;  // slope by differences
  int unreachable = 0;
  for (int k = 0; k < static_cast<int>(field.value.size()); ++k) {
    const Vec2 u = pl.scale * (field.centre(k) - pl.centre);
    const double hx =
        (target_height(target, u + Vec2(h, 0)) - target_height(target, u - Vec2(h, 0))) / (2 * h);
    const double hy =
        (target_height(target, u + Vec2(0, h)) - target_height(target, u - Vec2(0, h))) / (2 * h);
    // Shrink s sqrt(1 + slope^2) = (1 - rho) / lambda + rho along each stretched direction.
    double sum = 0.0;
    int directions = 0;
    for (int d = 0; d < 2; ++d) {
      const double l = lambda[d];
      if (!(l > 1.0)) continue;
      const double shrink = pl.scale * std::sqrt(1.0 + (d == 0 ? hx * hx : hy * hy));
      sum += (shrink - 1.0 / l) / (1.0 - 1.0 / l);
      ++directions;
    }
    const double asks = directions ? sum / directions : 0.5;
    m.asks_min = std::min(m.asks_min, asks);
    m.asks_max = std::max(m.asks_max, asks);
    if (asks < -0.02 || asks > 1.02) ++unreachable;
    m.density[k] = std::clamp(asks, 0.0, 1.0);
  }
  m.unreachable_share = static_cast<double>(unreachable) /
                        static_cast<double>(std::max<Eigen::Index>(1, field.value.size()));
  return m;
}

}  // namespace membra
