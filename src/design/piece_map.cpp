#include "membra/design/piece_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace membra {
namespace {

// The share of segment a-b inside the rectangle c +- h (Liang-Barsky clipping), and its
// derivatives in the half sides h.x and h.y.
struct Clip {
  double share = 0.0;
  Vec2 rate = Vec2::Zero();
};
Clip clip(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& h) {
  double t0 = 0.0, t1 = 1.0;
  Vec2 d0 = Vec2::Zero(), d1 = Vec2::Zero();  // d t0 / d h, d t1 / d h
  const Vec2 d = b - a;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {  // along the other axis: all in or all out across this one
      if (std::abs(a[k] - c[k]) > h[k]) return {};
      continue;
    }
    // Entering at |d| t = (c - h - a) sign(d), leaving at (c + h - a) sign(d).
    const double inv = 1.0 / std::abs(d[k]), s = d[k] > 0.0 ? 1.0 : -1.0;
    const double enter = (s * (c[k] - a[k]) - h[k]) * inv, leave = (s * (c[k] - a[k]) + h[k]) * inv;
    if (enter > t0) t0 = enter, d0 = Vec2::Zero(), d0[k] = -inv;
    if (leave < t1) t1 = leave, d1 = Vec2::Zero(), d1[k] = inv;
  }
  if (t1 <= t0) return {};
  return {t1 - t0, d1 - d0};
}

}  // namespace

PieceMap::PieceMap(const Stencil& stencil, double min_feature, const Membrane& m,
                   const Points& frame_x)
    : squares_(stencil.squares), outline_area_(stencil.outline_area) {
  for (size_t k = 0; k < squares_.size(); ++k) {
    const StencilSquare& q = squares_[k];
    const double lo = min_feature / q.cell.minCoeff(), hi = 1.0 - lo;
    if (q.scale >= 1.0 || hi <= lo) {
      variable_.push_back(-1);
      continue;
    }
    variable_.push_back(static_cast<int>(free_.size()));
    free_.push_back(static_cast<int>(k));
    lo_.push_back(lo);
    hi_.push_back(hi);
  }
  // The squares whose cell meets the element's bounding box: the only ones that can cover it.
  auto element = [&](const ResinFootprint& f) {
    Element e;
    if (f.count == 0) return e;
    Vec2 lo = f.segment[0].a, hi = lo;
    for (int k = 0; k < f.count; ++k) {
      const auto& g = f.segment[static_cast<size_t>(k)];
      e.segments.push_back({g.a, g.b, g.weight});
      lo = lo.cwiseMin(g.a).cwiseMin(g.b);
      hi = hi.cwiseMax(g.a).cwiseMax(g.b);
    }
    for (size_t k = 0; k < squares_.size(); ++k) {
      const Vec2 c = squares_[k].centre, h = 0.5 * squares_[k].cell;
      if ((lo.array() <= (c + h).array()).all() && (hi.array() >= (c - h).array()).all())
        e.near.push_back(static_cast<int>(k));
    }
    return e;
  };
  m.sheet.model.for_each_set([&](const auto& set) {
    auto& elements = elements_.emplace_back();
    for (int i = 0; i < set.size(); ++i) elements.push_back(element(set.footprint(i, frame_x)));
  });
}

double PieceMap::scale(int square, const Eigen::VectorXd& t) const {
  const int v = variable_[square];
  if (v < 0) return squares_[square].scale;
  return lo_[v] + std::clamp(t[v], 0.0, 1.0) * (hi_[v] - lo_[v]);
}

PieceMap::Coverage PieceMap::coverage(const Element& element, const Eigen::VectorXd& t) const {
  Coverage out;
  for (int k : element.near) {
    const StencilSquare& q = squares_[k];
    const Vec2 half = 0.5 * scale(k, t) * q.cell;
    const int v = variable_[k];
    double rate = 0.0;
    for (const Segment& g : element.segments) {
      const Clip c = clip(g.a, g.b, q.centre, half);
      out.fraction += g.weight * c.share;
      // d/dt through the half sides h = s c / 2, s = lo + t (hi - lo).
      if (v >= 0) rate += g.weight * c.rate.dot(0.5 * q.cell) * (hi_[v] - lo_[v]);
    }
    if (rate != 0.0) out.rate.emplace_back(v, rate);
  }
  out.fraction = std::min(out.fraction, 1.0);  // pieces do not overlap: only round-off
  return out;
}

PieceMap::Coverage PieceMap::element_coverage(size_t k, int i, const Eigen::VectorXd& t) const {
  return coverage(elements_[k][static_cast<size_t>(i)], t);
}

void PieceMap::apply(Membrane& m, const Eigen::VectorXd& t) const {
  if (t.size() != size()) throw std::invalid_argument("one variable per free piece");
  size_t k = 0;
  m.sheet.model.for_each_set([&](auto& set) {
    const auto& elements = elements_[k++];
    for (int i = 0; i < set.size(); ++i)
      if (!elements[static_cast<size_t>(i)].segments.empty())
        set.set_resin_fraction(i, coverage(elements[static_cast<size_t>(i)], t).fraction,
                               m.release());
  });
}

Eigen::VectorXd PieceMap::pull_back(const Membrane& m, const Eigen::VectorXd& t, const Points& x,
                                    const Points& w) const {
  const ElementRates r = element_force_sensitivity(m, x, w);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(size());
  for (size_t k = 0; k < elements_.size(); ++k)
    for (size_t i = 0; i < elements_[k].size(); ++i) {
      if (elements_[k][i].segments.empty()) continue;
      for (const auto& [v, d] : coverage(elements_[k][i], t).rate)
        out[v] += r.set[k][static_cast<Eigen::Index>(i)] * d;
    }
  return out;
}

Eigen::VectorXd PieceMap::variables() const {
  Eigen::VectorXd t(size());
  for (Eigen::Index v = 0; v < size(); ++v)
    t[v] = std::clamp((squares_[free_[v]].scale - lo_[v]) / (hi_[v] - lo_[v]), 0.0, 1.0);
  return t;
}

Stencil PieceMap::stencil(const Eigen::VectorXd& t) const {
  std::vector<StencilSquare> out = squares_;
  for (size_t k = 0; k < out.size(); ++k) out[k].scale = scale(static_cast<int>(k), t);
  return stencil_of(out, outline_area_);
}

}  // namespace membra
