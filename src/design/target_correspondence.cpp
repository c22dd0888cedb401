#include "membra/design/target_correspondence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "membra/design/conformal_flattening.hpp"

namespace membra {
namespace {

// The sheet's centre and extent on the frame (its particles').
struct Placement {
  Vec2 centre;
  double extent;
};
Placement placement(const Points& frame_x) {
  const Vec3 lo = frame_x.rowwise().minCoeff(), hi = frame_x.rowwise().maxCoeff();
  return {0.5 * (lo + hi).head<2>(), std::max(hi.x() - lo.x(), hi.y() - lo.y())};
}

// Barycentric coordinates of p in the plane triangle (a, b, c); nothing if it is degenerate.
std::optional<Vec3> barycentric(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  if (!(std::abs(det) > 0.0)) return std::nullopt;
  const Vec2 d = p - a;
  const double u = (d.x() * (c - a).y() - d.y() * (c - a).x()) / det;
  const double v = ((b - a).x() * d.y() - (b - a).y() * d.x()) / det;
  return Vec3(1.0 - u - v, u, v);
}

// Frame point -> target point, by either flattening.
class TargetMap {
 public:
  TargetMap(const TargetSurface& target, const Points& frame_x, Flattening flattening)
      : target_(target), flattening_(flattening), sheet_(placement(frame_x)) {
    if (flattening_ == Flattening::projection) {
      scale_ = target.diameter / sheet_.extent;
      return;
    }
    uv_ = conformal_flattening(target.x, target.triangles);
    uv_locator_.emplace(uv_, target.triangles);
    const Vec2 lo = uv_.rowwise().minCoeff(), hi = uv_.rowwise().maxCoeff();
    uv_centre_ = 0.5 * (lo + hi);
    scale_ = std::max(hi.x() - lo.x(), hi.y() - lo.y()) / sheet_.extent;
  }

  Vec3 operator()(const Vec2& frame_point) const {
    const Vec2 p = scale_ * (frame_point - sheet_.centre);
    if (flattening_ == Flattening::projection) return Vec3(p.x(), p.y(), target_height(target_, p));
    return on_surface(p + uv_centre_);
  }

 private:
  // The surface point whose flat image is q: by the barycentric coordinates of the triangle that
  // holds q, or beyond the flattening's edge, of the nearest one's (extended linearly).
  Vec3 on_surface(const Vec2& q) const {
    // The first triangle that holds q is among the locator's candidates, in the same order.
    for (int k : uv_locator_->candidates(q)) {
      const Triangle& t = target_.triangles[static_cast<size_t>(k)];
      const auto w = barycentric(uv_.col(t[0]), uv_.col(t[1]), uv_.col(t[2]), q);
      if (w && w->minCoeff() >= 0.0) return surface_point(t, *w);
    }
    double best = std::numeric_limits<double>::infinity();
    Vec3 w_best = Vec3(1.0, 0.0, 0.0);
    const Triangle* t_best = &target_.triangles.front();
    for (const Triangle& t : target_.triangles) {
      const auto w = barycentric(uv_.col(t[0]), uv_.col(t[1]), uv_.col(t[2]), q);
      if (!w) continue;
      const double outside = std::max(0.0, -w->minCoeff());  // 0 inside
      if (outside < best) best = outside, w_best = *w, t_best = &t;
      if (outside == 0.0) break;
    }
    return surface_point(*t_best, w_best);
  }

  Vec3 surface_point(const Triangle& t, const Vec3& w) const {
    return w[0] * target_.x.col(t[0]) + w[1] * target_.x.col(t[1]) + w[2] * target_.x.col(t[2]);
  }

  const TargetSurface& target_;
  Flattening flattening_;
  Placement sheet_;
  double scale_ = 1.0;
  Eigen::Matrix2Xd uv_;
  std::optional<TriangleLocator> uv_locator_;
  Vec2 uv_centre_ = Vec2::Zero();
};

}  // namespace

double target_height(const TargetSurface& target, const Vec2& p) {
  if (!p.allFinite()) return std::numeric_limits<double>::quiet_NaN();  // as a scan would
  const Points& x = target.x;
  // The first triangle (in the mesh's order) that holds p; the locator's candidates are in that
  // order and include every triangle that can hold p, so it finds the same one.
  const auto height_in = [&](const Triangle& t) -> std::optional<double> {
    const auto w =
        barycentric(x.col(t[0]).head<2>(), x.col(t[1]).head<2>(), x.col(t[2]).head<2>(), p);
    constexpr double eps = 1e-9;
    if (!w || w->minCoeff() < -eps) return std::nullopt;
    return (*w)[0] * x(2, t[0]) + (*w)[1] * x(2, t[1]) + (*w)[2] * x(2, t[2]);
  };
  if (target.locator) {
    for (int k : target.locator->candidates(p))
      if (const auto z = height_in(target.triangles[static_cast<size_t>(k)])) return *z;
  } else {
    for (const Triangle& t : target.triangles)
      if (const auto z = height_in(t)) return *z;
  }
  Eigen::Index nearest = 0;
  (x.topRows<2>().colwise() - p).colwise().squaredNorm().minCoeff(&nearest);
  return x(2, nearest);
}

Correspondence target_correspondence(const TargetSurface& target, const Points& frame_x,
                                     const Eigen::VectorXd& weights, Flattening flattening) {
  const TargetMap map(target, frame_x, flattening);
  Correspondence c{Points(3, frame_x.cols()), weights};
  for (Eigen::Index i = 0; i < frame_x.cols(); ++i) c.target.col(i) = map(frame_x.col(i).head<2>());
  return c;
}

MetricStart metric_start(const TargetSurface& target, const Points& frame_x,
                         const DensityField& field, const Vec2& lambda, Flattening flattening) {
  const TargetMap map(target, frame_x, flattening);
  MetricStart m;
  m.density.resize(field.value.size());
  m.asks_min = std::numeric_limits<double>::infinity();
  m.asks_max = -m.asks_min;
  const double h = 0.25 * field.cell_size().minCoeff();  // stretch by central differences
  int unreachable = 0;
  for (int k = 0; k < static_cast<int>(field.value.size()); ++k) {
    const Vec2 p = field.centre(k);
    // Shrink |dX/dP| = (1 - rho) / lambda + rho along each stretched direction.
    double sum = 0.0;
    int directions = 0;
    for (int d = 0; d < 2; ++d) {
      const double l = lambda[d];
      if (!(l > 1.0)) continue;
      const Vec2 step = h * Vec2::Unit(d);
      const double shrink = (map(p + step) - map(p - step)).norm() / (2.0 * h);
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
