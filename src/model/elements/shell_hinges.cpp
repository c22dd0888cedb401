#include "membra/model/elements/shell_hinges.hpp"

#include <map>
#include <stdexcept>
#include <utility>

#include "membra/model/elements/hinge_kernel.hpp"
#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"

namespace membra {

static_assert(ElementSet<ShellHinges>);

void ShellHinges::add(const std::array<int, 4>& ids, const std::array<Vec3, 4>& p, double d) {
  const Vec3 e = p[1] - p[0];
  const double a1 = 0.5 * e.cross(p[2] - p[0]).norm(), a2 = 0.5 * e.cross(p[3] - p[0]).norm();
  if (!(a1 > 0.0) || !(a2 > 0.0) || !(d >= 0.0))
    throw std::invalid_argument("shell hinge: a degenerate side or a negative stiffness");
  v.push_back(ids);
  side_area.push_back({a1, a2});
  side_d.push_back({d, d});
  side_resin.push_back({false, false});
  edge_squared.push_back(e.squaredNorm());
  stiffness.push_back(0.0);
  rest_angle.push_back(0.0);
  update_stiffness(size() - 1);
}

int ShellHinges::add_mesh(const std::vector<std::array<int, 3>>& triangles, const Points& reference,
                          double d) {
  // Each directed edge with the vertex to its left; an interior edge has both directions.
  std::map<std::pair<int, int>, int> left;
  for (const auto& t : triangles)
    for (size_t k = 0; k < 3; ++k) left[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
  int added = 0;
  for (const auto& [edge, c] : left) {
    const auto [a, b] = edge;
    if (a > b) continue;
    const auto other = left.find({b, a});
    if (other == left.end()) continue;
    const std::array<int, 4> ids{a, b, c, other->second};
    add(ids, {reference.col(a), reference.col(b), reference.col(c), reference.col(ids[3])}, d);
    ++added;
  }
  return added;
}

void ShellHinges::filter(const std::vector<bool>& keep) {
  keep_where(v, keep);
  keep_where(stiffness, keep);
  keep_where(rest_angle, keep);
  keep_where(side_area, keep);
  keep_where(side_d, keep);
  keep_where(side_resin, keep);
  keep_where(edge_squared, keep);
}

void ShellHinges::update_stiffness(int i) {
  const auto k = static_cast<size_t>(i);
  const auto& a = side_area[k];
  const auto& d = side_d[k];
  const double area = a[0] + a[1];
  const double compliance = (d[0] > 0.0 ? a[0] / d[0] : 0.0) + (d[1] > 0.0 ? a[1] / d[1] : 0.0);
  const double d_edge = d[0] > 0.0 && d[1] > 0.0 ? area / compliance : 0.0;
  stiffness[k] = 0.5 * d_edge * edge_squared[k] / area;
}

double ShellHinges::energy(int i, const Points& x) const {
  const auto& p = v[static_cast<size_t>(i)];
  const double d = hinge_eval(x.col(p[0]), x.col(p[1]), x.col(p[2]), x.col(p[3])).theta -
                   rest_angle[static_cast<size_t>(i)];
  return stiffness[static_cast<size_t>(i)] * d * d;
}

void ShellHinges::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const auto k = static_cast<size_t>(i);
    if (stiffness[k] == 0.0) continue;
    const auto& p = v[k];
    const HingeEval h = hinge_eval(x.col(p[0]), x.col(p[1]), x.col(p[2]), x.col(p[3]));
    const double m = 2.0 * stiffness[k] * (h.theta - rest_angle[k]);
    for (int c = 0; c < 4; ++c) f.col(p[c]) -= m * h.grad[c];
  }
}

Eigen::Matrix<double, 12, 12> ShellHinges::hessian(int i, const Points& x, bool project) const {
  const auto k = static_cast<size_t>(i);
  const auto& p = v[k];
  const HingeEval h = hinge_eval(x.col(p[0]), x.col(p[1]), x.col(p[2]), x.col(p[3]));
  // E = k (theta - theta0)^2: 2k grad theta grad theta^T + 2k (theta - theta0) Hess theta.
  Eigen::Matrix<double, 12, 1> g;
  for (int c = 0; c < 4; ++c) g.segment<3>(3 * c) = h.grad[c];
  const Eigen::Matrix<double, 12, 12> full =
      (2.0 * stiffness[k]) * g * g.transpose() +
      hinge_hessian(x.col(p[0]), x.col(p[1]), x.col(p[2]), x.col(p[3]),
                    2.0 * stiffness[k] * (h.theta - rest_angle[k]), false);
  return project ? project_psd(full) : full;
}

void ShellHinges::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    if (!active(i)) continue;
    const Eigen::Matrix<double, 12, 12> h = hessian(i, x, true);
    const auto& p = v[static_cast<size_t>(i)];
    for (int c = 0; c < 4; ++c) diag[p[c]] += h.block<3, 3>(3 * c, 3 * c).trace() / 3.0;
  }
}

int ShellHinges::impregnate(const Impregnation& at) {
  const double d_resin = bending_stiffness(at.resin);
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    const auto& p = v[k];
    bool any = false;
    for (int side = 0; side < 2; ++side) {
      const Vec3 c = (at.x.col(p[0]) + at.x.col(p[1]) + at.x.col(p[2 + side])) / 3.0;
      const auto s = static_cast<size_t>(side);
      if (side_resin[k][s] || !at.pattern.contains(c.head<2>())) continue;
      side_d[k][s] += d_resin;
      side_resin[k][s] = true;
      any = true;
    }
    if (!any) continue;
    update_stiffness(i);
    ++count;
  }
  return count;
}

bool ShellHinges::severed(int i, const CrossesCut& crosses) const {
  const auto& p = v[static_cast<size_t>(i)];
  auto cut_triangle = [&](int a, int b, int c) {
    return crosses(a, b) || crosses(b, c) || crosses(c, a);
  };
  return cut_triangle(p[0], p[1], p[2]) || cut_triangle(p[1], p[0], p[3]);
}

void ShellHinges::carry(const ShellHinges& old, const Rebuild& r) {
  for (int i = 0; i < old.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    std::array<int, 4> p;
    if (!r.map(old.v[k], p)) continue;
    v.push_back(p);
    stiffness.push_back(old.stiffness[k]);
    rest_angle.push_back(old.rest_angle[k]);
    side_area.push_back(old.side_area[k]);
    side_d.push_back(old.side_d[k]);
    side_resin.push_back(old.side_resin[k]);
    edge_squared.push_back(old.edge_squared[k]);
  }
}

}  // namespace membra
