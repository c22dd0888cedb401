#include "membra/model/pattern.hpp"

#include "membra/model/polygon_index.hpp"
#include "membra/model/segment_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace membra {
namespace {

class Strip final : public Pattern {
 public:
  Strip(std::vector<Vec2> pts, double width) : pts_(std::move(pts)), r_(0.5 * width) {
    if (pts_.empty() || !(width > 0.0))
      throw std::invalid_argument("strip: needs points and width > 0");
    for (const auto& p : pts_) box_.extend(p);
    box_.min -= Vec2::Constant(r_);
    box_.max += Vec2::Constant(r_);
  }
  bool contains(const Vec2& p) const override {
    if ((p.array() < box_.min.array()).any() || (p.array() > box_.max.array()).any()) return false;
    const double r2 = r_ * r_;
    if (pts_.size() == 1) return (p - pts_[0]).squaredNorm() <= r2;
    for (size_t i = 0; i + 1 < pts_.size(); ++i)
      if (segment_distance2(p, pts_[i], pts_[i + 1]) <= r2) return true;
    return false;
  }
  Box2 bounds() const override { return box_; }
  double field(const Vec2& p) const override {
    double d2 = (p - pts_[0]).squaredNorm();
    for (size_t i = 0; i + 1 < pts_.size(); ++i)
      d2 = std::min(d2, segment_distance2(p, pts_[i], pts_[i + 1]));
    return std::sqrt(d2) - r_;
  }
  bool field_is_distance() const override { return true; }

 private:
  std::vector<Vec2> pts_;
  double r_;
  Box2 box_;
};

class Ellipse final : public Pattern {
 public:
  Ellipse(Vec2 c, double a, double b, double angle)
      : c_(c), a_(a), b_(b), cos_(std::cos(angle)), sin_(std::sin(angle)) {
    if (!(a > 0.0) || !(b > 0.0)) throw std::invalid_argument("ellipse: radii must be > 0");
  }
  bool contains(const Vec2& p) const override {
    const Vec2 d = p - c_;
    const double u = cos_ * d.x() + sin_ * d.y(), v = -sin_ * d.x() + cos_ * d.y();
    return (u / a_) * (u / a_) + (v / b_) * (v / b_) <= 1.0;
  }
  double field(const Vec2& p) const override {
    // (r - 1) min(a, b), r the elliptic radius: smooth, zero on the outline, ~ distance near it.
    const Vec2 d = p - c_;
    const double u = cos_ * d.x() + sin_ * d.y(), v = -sin_ * d.x() + cos_ * d.y();
    return (std::hypot(u / a_, v / b_) - 1.0) * std::min(a_, b_);
  }
  Box2 bounds() const override {
    const double hx = std::hypot(a_ * cos_, b_ * sin_), hy = std::hypot(a_ * sin_, b_ * cos_);
    return {c_ - Vec2(hx, hy), c_ + Vec2(hx, hy)};
  }
  std::vector<PlaneCurve> exact_outline() const override {
    return {
        PlaneCurve::ellipse_arc(c_, a_, b_, std::atan2(sin_, cos_), 0.0, 2.0 * std::numbers::pi)};
  }

 private:
  Vec2 c_;
  double a_, b_, cos_, sin_;
};

class Polygon final : public Pattern {
 public:
  explicit Polygon(std::vector<Vec2> v) : index_(std::move(v)) {}
  bool contains(const Vec2& p) const override { return index_.contains(p); }
  Box2 bounds() const override { return index_.bounds(); }
  double field(const Vec2& p) const override {
    // Exact within three grid cells of the outline, where outlines are traced; beyond, an upper
    // bound of the distance (still at least the distance to the bounds, as a union expects).
    const double d = index_.distance(p, 3);
    return contains(p) ? -d : d;
  }
  bool field_is_distance() const override { return true; }
  std::vector<PlaneCurve> exact_outline() const override {
    const auto& v = index_.vertices();
    std::vector<PlaneCurve> edges;
    for (size_t i = 0; i < v.size(); ++i)
      if (v[i] != v[(i + 1) % v.size()])
        edges.push_back(PlaneCurve::segment(v[i], v[(i + 1) % v.size()]));
    return edges;
  }

 private:
  PolygonIndex index_;  // edges on a grid: 10^5-vertex outlines stay fast
};

class Raster final : public Pattern {
 public:
  Raster(std::vector<float> g, int w, int h, Vec2 origin, Vec2 size, double threshold, bool invert)
      : g_(std::move(g)),
        w_(w),
        h_(h),
        origin_(origin),
        size_(size),
        threshold_(threshold),
        invert_(invert) {
    if (w <= 0 || h <= 0 || g_.size() != static_cast<size_t>(w) * h)
      throw std::invalid_argument("image: empty or inconsistent raster");
    if (!(size.x() > 0.0) || !(size.y() > 0.0))
      throw std::invalid_argument("image: size must be > 0");
  }
  // Resin where the bilinear grey level is on the resin side of the threshold: the same level
  // the continuum's mesh follows (field), so no triangle of it lies across the outline; on a
  // black-and-white image that is the pixels' own edges, their corners cut.
  bool contains(const Vec2& p) const override {
    const Vec2 t = (p - origin_).cwiseQuotient(size_);
    if (t.x() < 0.0 || t.y() < 0.0 || t.x() >= 1.0 || t.y() >= 1.0) return false;
    return field(p) < 0.0;
  }
  Box2 bounds() const override { return {origin_, origin_ + size_}; }
  double field(const Vec2& p) const override {
    // Bilinear grey value against the threshold, scaled to about a pixel (m) per unit.
    const Vec2 t = (p - origin_).cwiseQuotient(size_);
    const double px = t.x() * w_ - 0.5, py = (1.0 - t.y()) * h_ - 0.5;
    auto at = [&](int c, int r) {
      if (c < 0 || r < 0 || c >= w_ || r >= h_) return invert_ ? 0.0 : 1.0;  // outside: no resin
      return static_cast<double>(g_[static_cast<size_t>(r) * w_ + c]);
    };
    const int c0 = static_cast<int>(std::floor(px)), r0 = static_cast<int>(std::floor(py));
    const double fx = px - c0, fy = py - r0;
    const double g = (1 - fy) * ((1 - fx) * at(c0, r0) + fx * at(c0 + 1, r0)) +
                     fy * ((1 - fx) * at(c0, r0 + 1) + fx * at(c0 + 1, r0 + 1));
    const double pixel = std::max(size_.x() / w_, size_.y() / h_);
    return (invert_ ? threshold_ - g : g - threshold_) * pixel;
  }

 private:
  std::vector<float> g_;
  int w_, h_;
  Vec2 origin_, size_;
  double threshold_;
  bool invert_;
};

class Union final : public Pattern {
 public:
  explicit Union(std::vector<PatternPtr> parts) : parts_(std::move(parts)) {
    for (const auto& p : parts_) {
      part_boxes_.push_back(p->bounds());
      box_.extend(p->bounds());
    }
  }
  bool contains(const Vec2& p) const override {
    return std::any_of(parts_.begin(), parts_.end(), [&](const auto& q) { return q->contains(p); });
  }
  double field(const Vec2& p) const override {
    // The minimum of the parts' fields; a distance part farther off than the minimum so far
    // cannot lower it (its field is at least its box's distance), so it is not evaluated:
    // the same value, much faster for stencils of many pieces.
    double f = std::numeric_limits<double>::infinity();
    for (const auto& q : parts_)
      if (!q->field_is_distance()) f = std::min(f, q->field(p));
    for (size_t i = 0; i < parts_.size(); ++i) {
      if (!parts_[i]->field_is_distance()) continue;
      const Box2& b = part_boxes_[i];
      const Vec2 out = (b.min - p).cwiseMax(p - b.max).cwiseMax(0.0);
      if (out.squaredNorm() > 0.0 && out.norm() >= f) continue;
      f = std::min(f, parts_[i]->field(p));
    }
    return f;
  }
  Box2 bounds() const override { return box_; }
  Combination combination() const override { return Combination::union_of; }
  std::vector<PatternPtr> parts() const override { return parts_; }

 private:
  std::vector<PatternPtr> parts_;
  std::vector<Box2> part_boxes_;
  Box2 box_;
};

class Difference final : public Pattern {
 public:
  explicit Difference(std::vector<PatternPtr> parts) : parts_(std::move(parts)) {
    if (parts_.empty()) throw std::invalid_argument("difference: needs at least one pattern");
  }
  bool contains(const Vec2& p) const override {
    if (!parts_[0]->contains(p)) return false;
    for (size_t i = 1; i < parts_.size(); ++i)
      if (parts_[i]->contains(p)) return false;
    return true;
  }
  Box2 bounds() const override { return parts_[0]->bounds(); }
  double field(const Vec2& p) const override {
    double f = parts_[0]->field(p);
    for (size_t i = 1; i < parts_.size(); ++i) f = std::max(f, -parts_[i]->field(p));
    return f;
  }
  Combination combination() const override { return Combination::difference_of; }
  std::vector<PatternPtr> parts() const override { return parts_; }

 private:
  std::vector<PatternPtr> parts_;
};

// Samples of a closed or open curve as a polyline, for ring and hyperbola bands.
std::vector<Vec2> ellipse_outline(Vec2 c, double a, double b, double angle) {
  const int n = 720;
  std::vector<Vec2> pts;
  for (int i = 0; i <= n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const Vec2 q(a * std::cos(t), b * std::sin(t));
    pts.push_back(c + Vec2(std::cos(angle) * q.x() - std::sin(angle) * q.y(),
                           std::sin(angle) * q.x() + std::cos(angle) * q.y()));
  }
  return pts;
}

}  // namespace

PatternPtr make_strip(std::vector<Vec2> points, double width) {
  return std::make_shared<Strip>(std::move(points), width);
}

PatternPtr make_ellipse(Vec2 centre, double a, double b, double angle) {
  return std::make_shared<Ellipse>(centre, a, b, angle);
}

PatternPtr make_ellipse_ring(Vec2 centre, double a, double b, double angle, double width) {
  if (!(a > 0.0) || !(b > 0.0)) throw std::invalid_argument("ellipse: radii must be > 0");
  return make_strip(ellipse_outline(centre, a, b, angle), width);
}

PatternPtr make_hyperbola(Vec2 centre, double a, double b, double angle, double width, bool along_x,
                          double reach) {
  if (!(a > 0.0) || !(b > 0.0)) throw std::invalid_argument("hyperbola: a and b must be > 0");
  // Parametrize x = +-a cosh t, y = b sinh t (or swapped); sinh(t_max) min(a, b) >= reach makes
  // the branches leave the disc of radius `reach`, and points beyond 1.5 reach are dropped.
  const double t_max = std::asinh(reach / std::min(a, b));
  std::vector<PatternPtr> branches;
  for (int sign : {-1, 1}) {
    std::vector<Vec2> pts;
    const int n = 400;
    for (int i = -n; i <= n; ++i) {
      const double t = t_max * i / n;
      Vec2 q = along_x ? Vec2(sign * a * std::cosh(t), b * std::sinh(t))
                       : Vec2(a * std::sinh(t), sign * b * std::cosh(t));
      if (q.norm() > 1.5 * reach) continue;
      pts.push_back(centre + Vec2(std::cos(angle) * q.x() - std::sin(angle) * q.y(),
                                  std::sin(angle) * q.x() + std::cos(angle) * q.y()));
    }
    branches.push_back(make_strip(std::move(pts), width));
  }
  return make_union(std::move(branches));
}

PatternPtr make_polygon(std::vector<Vec2> vertices) {
  return std::make_shared<Polygon>(std::move(vertices));
}

PatternPtr make_raster(std::vector<float> grey, int width, int height, Vec2 origin, Vec2 size,
                       double threshold, bool invert) {
  return std::make_shared<Raster>(std::move(grey), width, height, origin, size, threshold, invert);
}

PatternPtr make_union(std::vector<PatternPtr> parts) {
  if (parts.size() == 1) return std::move(parts[0]);  // no wrapper to walk through per query
  return std::make_shared<Union>(std::move(parts));
}

PatternPtr make_difference(std::vector<PatternPtr> parts) {
  return std::make_shared<Difference>(std::move(parts));
}

double fraction_inside(const Pattern& pattern, const Vec2& a, const Vec2& b, int samples) {
  int in = 0;
  for (int k = 0; k < samples; ++k)
    if (pattern.contains(a + (k + 0.5) / samples * (b - a))) ++in;
  return static_cast<double>(in) / samples;
}

}  // namespace membra
