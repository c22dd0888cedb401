#include "membra/design/piece_map.hpp"

#include <algorithm>
#include <stdexcept>

#include "membra/design/resin_density.hpp"

namespace membra {
namespace {

// The share of [b0, b1] inside [c - h, c + h], and its derivative in h.
std::pair<double, double> overlap(double b0, double b1, double c, double h) {
  const double o = std::min(b1, c + h) - std::max(b0, c - h);
  if (o <= 0.0) return {0.0, 0.0};
  const double inside_ends = (c + h < b1 ? 1.0 : 0.0) + (c - h > b0 ? 1.0 : 0.0);
  return {o / (b1 - b0), inside_ends / (b1 - b0)};
}

template <typename Nodes>
auto box_of(const Points& x, const Nodes& nodes, const Vec2& spacing) {
  Vec2 lo = x.col(nodes[0]).template head<2>(), hi = lo;
  for (int p : nodes) {
    lo = lo.cwiseMin(x.col(p).template head<2>());
    hi = hi.cwiseMax(x.col(p).template head<2>());
  }
  // An element along a grid line has no width across it: it stands for half a spacing each side.
  for (int k = 0; k < 2; ++k)
    if (hi[k] - lo[k] < 1e-6 * spacing[k]) lo[k] -= 0.5 * spacing[k], hi[k] += 0.5 * spacing[k];
  return std::pair{lo, hi};
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
  const Vec2 spacing(m.sheet.grid.hx() * m.stretch.x(), m.sheet.grid.hy() * m.stretch.y());
  auto near = [&](const Box& b) {
    std::vector<int> out;
    for (size_t k = 0; k < squares_.size(); ++k) {
      const Vec2 c = squares_[k].centre, h = 0.5 * squares_[k].cell;
      if ((b.lo.array() < (c + h).array()).all() && (b.hi.array() > (c - h).array()).all())
        out.push_back(static_cast<int>(k));
    }
    return out;
  };
  const Springs& sp = m.sheet.model.springs;
  for (int s = 0; s < sp.size(); ++s) {
    const auto [lo, hi] = box_of(frame_x, std::array<int, 2>{sp.a[s], sp.b[s]}, spacing);
    spring_box_.push_back({lo, hi});
    spring_near_.push_back(near(spring_box_.back()));
    added_.push_back(sp.family[s] == SpringFamily::added);
  }
  const Bending& b = m.sheet.model.bending;
  for (int e = 0; e < b.size(); ++e) {
    const auto [lo, hi] = box_of(frame_x, b.v[e], spacing);
    bend_box_.push_back({lo, hi});
    bend_near_.push_back(near(bend_box_.back()));
  }
}

double PieceMap::scale(int square, const Eigen::VectorXd& t) const {
  const int v = variable_[square];
  if (v < 0) return squares_[square].scale;
  return lo_[v] + std::clamp(t[v], 0.0, 1.0) * (hi_[v] - lo_[v]);
}

PieceMap::Coverage PieceMap::coverage(const Box& box, const std::vector<int>& near,
                                      const Eigen::VectorXd& t) const {
  Coverage out;
  for (int k : near) {
    const StencilSquare& q = squares_[k];
    const double s = scale(k, t);
    const auto [ox, dx] = overlap(box.lo.x(), box.hi.x(), q.centre.x(), 0.5 * s * q.cell.x());
    const auto [oy, dy] = overlap(box.lo.y(), box.hi.y(), q.centre.y(), 0.5 * s * q.cell.y());
    out.fraction += ox * oy;
    const int v = variable_[k];
    if (v < 0 || ox * oy <= 0.0) continue;
    // d/dt through the half sides h = s c / 2, s = lo + t (hi - lo).
    const double ds = hi_[v] - lo_[v];
    const double rate = (dx * oy * 0.5 * q.cell.x() + ox * dy * 0.5 * q.cell.y()) * ds;
    if (rate != 0.0) out.rate.emplace_back(v, rate);
  }
  out.fraction = std::min(out.fraction, 1.0);  // pieces do not overlap: only round-off
  return out;
}

PieceMap::Coverage PieceMap::spring_coverage(int s, const Eigen::VectorXd& t) const {
  return coverage(spring_box_[s], spring_near_[s], t);
}

PieceMap::Coverage PieceMap::bend_coverage(int e, const Eigen::VectorXd& t) const {
  return coverage(bend_box_[e], bend_near_[e], t);
}

void PieceMap::apply(Membrane& m, const Eigen::VectorXd& t) const {
  if (t.size() != size()) throw std::invalid_argument("one variable per free piece");
  for (size_t s = 0; s < spring_box_.size(); ++s)
    if (!added_[s])
      set_spring_fraction(m, static_cast<int>(s), spring_coverage(static_cast<int>(s), t).fraction);
  for (size_t e = 0; e < bend_box_.size(); ++e)
    set_bend_fraction(m, static_cast<int>(e), bend_coverage(static_cast<int>(e), t).fraction);
}

Eigen::VectorXd PieceMap::pull_back(const Membrane& m, const Eigen::VectorXd& t, const Points& x,
                                    const Points& w) const {
  const ElementRates r = element_force_sensitivity(m, x, w);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(size());
  for (size_t s = 0; s < spring_box_.size(); ++s)
    if (!added_[s])
      for (const auto& [v, d] : spring_coverage(static_cast<int>(s), t).rate)
        out[v] += r.spring[static_cast<Eigen::Index>(s)] * d;
  for (size_t e = 0; e < bend_box_.size(); ++e)
    for (const auto& [v, d] : bend_coverage(static_cast<int>(e), t).rate)
      out[v] += r.bend[static_cast<Eigen::Index>(e)] * d;
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
