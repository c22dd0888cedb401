#include "membra/model/elements/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "membra/geometry/box_grid.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<SelfContact>);

namespace {

Vec3 corner(const Points& x, const Triangle& t, int k) {
  return x.col(t[k]);
}

double distance2(const Points& x, int p, const Triangle& t) {
  return point_triangle_distance(x.col(p), corner(x, t, 0), corner(x, t, 1), corner(x, t, 2)).d2;
}

}  // namespace

void SelfContact::cover(const std::vector<Triangle>& triangles, const Points& rest_positions,
                        double g, double k, double excl) {
  if (!(g > 0.0) || !std::isfinite(g))
    throw std::invalid_argument("the contact gap must be positive");
  if (!(k > 0.0) || !std::isfinite(k))
    throw std::invalid_argument("the contact pressure must be positive");
  if (!(excl >= 2.0 * g) || !std::isfinite(excl))
    throw std::invalid_argument("the contact exclusion must be at least twice the gap");
  triangle = triangles;
  rest = rest_positions;
  gap = g;
  pressure = k;
  exclusion = excl;
  area.assign(static_cast<size_t>(rest.cols()), 0.0);
  for (const Triangle& t : triangle) {
    const double a = 0.5 * (corner(rest, t, 1) - corner(rest, t, 0))
                               .cross(corner(rest, t, 2) - corner(rest, t, 0))
                               .norm();
    for (int c = 0; c < 3; ++c) area[static_cast<size_t>(t[c])] += a / 3.0;
  }
  pairs_.clear();
}

void SelfContact::recover(const std::vector<Triangle>& triangles, const Points& rest_positions) {
  if (enabled()) cover(triangles, rest_positions, gap, pressure, exclusion);
}

void SelfContact::carry(const SelfContact& old, const Rebuild& r) {
  triangle.clear();
  pairs_.clear();
  if (old.enabled())
    cover(r.new_sheet.triangles, r.new_sheet.model.reference, old.gap, old.pressure, old.exclusion);
}

std::vector<std::array<int, 4>> SelfContact::near_pairs(const Points& x, double radius) const {
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(triangle.size());
  for (const Triangle& t : triangle) boxes.push_back(triangle_box(x, t, radius));
  const double cell = std::max(radius, BoxGrid::mean_size(boxes));
  const BoxGrid grid(std::move(boxes), cell);
  std::vector<std::array<int, 4>> out;
  std::vector<int> seen(triangle.size(), -1);
  for (int p = 0; p < static_cast<int>(area.size()); ++p) {
    if (area[static_cast<size_t>(p)] <= 0.0) continue;  // on no triangle
    const Vec3 xp = x.col(p);
    grid.overlapping(Eigen::AlignedBox3d(xp, xp), [&](int b) {
      if (std::exchange(seen[static_cast<size_t>(b)], p) == p) return;
      const Triangle& t = triangle[static_cast<size_t>(b)];
      if (t[0] == p || t[1] == p || t[2] == p || !grid.box(b).contains(xp)) return;
      if (distance2(x, p, t) >= radius * radius) return;
      if (distance2(rest, p, t) < exclusion * exclusion) return;
      out.push_back({p, t[0], t[1], t[2]});
    });
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool SelfContact::refresh(const Points& x) const {
  if (!enabled()) return false;
  // Two searches when the list changes, one when it does not (most calls): one search at 2 gaps
  // for both took longer than the one at 1.5 (docs/performance.md, BM_SelfContactRefresh).
  const auto near = near_pairs(x, 1.5 * gap);
  if (std::includes(pairs_.begin(), pairs_.end(), near.begin(), near.end())) return false;
  pairs_ = near_pairs(x, 2.0 * gap);
  return true;
}

double SelfContact::step_limit(const Points& x, const Points& d, const Points& e) const {
  if (!enabled()) return 1.0;
  const bool curved = e.cols() == d.cols();
  Eigen::VectorXd reach = d.colwise().norm().transpose();
  if (curved) reach += e.colwise().norm().transpose();
  // A step that would carry a particle further than kMaxReach gaps is first shortened to that:
  // the broad phase's boxes stay bounded (a soft mode's step can be metres long).
  const double longest = reach.size() ? reach.maxCoeff() : 0.0;
  if (!std::isfinite(longest)) return 1.0;  // the line search rejects a step that is not finite
  const double alpha0 = longest > kMaxReach * gap ? kMaxReach * gap / longest : 1.0;
  reach *= alpha0;
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(triangle.size());
  for (const Triangle& t : triangle)
    boxes.push_back(triangle_box(x, t, gap + std::max({reach[t[0]], reach[t[1]], reach[t[2]]})));
  const double cell = std::max(gap, BoxGrid::mean_size(boxes));
  const BoxGrid grid(std::move(boxes), cell);
  double alpha = alpha0;
  std::vector<int> seen(triangle.size(), -1);
  for (int p = 0; p < static_cast<int>(area.size()); ++p) {
    if (area[static_cast<size_t>(p)] <= 0.0) continue;
    const Vec3 xp = x.col(p);
    const Eigen::AlignedBox3d query(xp.array() - reach[p], xp.array() + reach[p]);
    grid.overlapping(query, [&](int b) {
      if (std::exchange(seen[static_cast<size_t>(b)], p) == p) return;
      const Triangle& t = triangle[static_cast<size_t>(b)];
      if (t[0] == p || t[1] == p || t[2] == p || !grid.box(b).intersects(query)) return;
      double rel = 0.0;  // how far p may move relative to the triangle per unit alpha
      for (int c = 0; c < 3; ++c)
        rel = std::max(rel, (d.col(p) - d.col(t[c])).norm() +
                                (curved ? (e.col(p) - e.col(t[c])).norm() : 0.0));
      if (!(rel > 0.0)) return;
      // The triangle's box (unpadded) is no farther than the triangle: a cheap first test.
      const double box = std::sqrt(triangle_box(x, t, 0.0).squaredExteriorDistance(xp));
      if (box - rel * alpha >= gap) return;
      const double d0 = std::sqrt(distance2(x, p, t));
      if (d0 - rel * alpha >= gap) return;  // cannot reach the gap within the step so far
      if (distance2(rest, p, t) < exclusion * exclusion) return;
      const std::array<int, 4> key{p, t[0], t[1], t[2]};
      const bool listed = std::binary_search(pairs_.begin(), pairs_.end(), key);
      alpha = std::min(alpha, listed || d0 <= gap ? 0.9 * d0 / rel : (d0 - gap) / rel);
    });
  }
  return alpha;
}

double SelfContact::weight(int i) const {
  const double a = area[static_cast<size_t>(pairs_[static_cast<size_t>(i)][0])];
  return pressure * a / (gap * gap * gap);
}

double SelfContact::energy(int i, const Points& x) const {
  const auto& q = pairs_[static_cast<size_t>(i)];
  return contact_energy(x.col(q[0]), x.col(q[1]), x.col(q[2]), x.col(q[3]), weight(i), gap * gap);
}

void SelfContact::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const auto& q = pairs_[static_cast<size_t>(i)];
    const ContactGradient g =
        contact_gradient(x.col(q[0]), x.col(q[1]), x.col(q[2]), x.col(q[3]), weight(i), gap * gap);
    for (int k = 0; k < 4; ++k) f.col(q[static_cast<size_t>(k)]) -= g.segment<3>(3 * k);
  }
}

ContactHessian SelfContact::hessian(int i, const Points& x, bool project) const {
  const auto& q = pairs_[static_cast<size_t>(i)];
  return contact_hessian(x.col(q[0]), x.col(q[1]), x.col(q[2]), x.col(q[3]), weight(i), gap * gap,
                         project);
}

void SelfContact::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    const ContactHessian h = hessian(i, x, true);
    for (int k = 0; k < 4; ++k)
      diag[static_cast<size_t>(pairs_[static_cast<size_t>(i)][static_cast<size_t>(k)])] +=
          h.diagonal().segment<3>(3 * k).maxCoeff();
  }
}

void SelfContact::filter(const std::vector<bool>& keep) {
  keep_where(pairs_, keep);
}

ContactReading SelfContact::read(const Points& x) const {
  ContactReading r;
  r.min_distance = gap;
  for (int i = 0; i < size(); ++i) {
    const auto& q = pairs_[static_cast<size_t>(i)];
    const double d = std::sqrt(distance2(x, q[0], {q[1], q[2], q[3]}));
    r.min_distance = std::min(r.min_distance, d);
    if (d >= gap) continue;
    ++r.touching;
    r.push +=
        contact_gradient(x.col(q[0]), x.col(q[1]), x.col(q[2]), x.col(q[3]), weight(i), gap * gap)
            .head<3>()
            .norm();
  }
  return r;
}

}  // namespace membra
