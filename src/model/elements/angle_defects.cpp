#include "membra/model/elements/angle_defects.hpp"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"

namespace membra {

static_assert(ElementSet<AngleDefects>);

namespace {

template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;

template <typename T>
T corner_angle(const V3<T>& at, const V3<T>& a, const V3<T>& b) {
  using std::atan2;
  const V3<T> u = a - at, w = b - at;
  return atan2(u.cross(w).norm(), u.dot(w));
}

// d theta / d(at, a, b) for the corner angle theta = atan2(|u x w|, u . w), u = a - at,
// w = b - at: d|u x w|/du = (w x n)/|n|, d|u x w|/dw = (n x u)/|n| with n = u x w.
template <typename T>
std::array<V3<T>, 3> corner_gradient(const V3<T>& at, const V3<T>& a, const V3<T>& b) {
  const V3<T> u = a - at, w = b - at, n = u.cross(w);
  const T s = n.norm(), c = u.dot(w), r = s * s + c * c;
  const V3<T> ds_du = w.cross(n) / s, ds_dw = n.cross(u) / s;
  const V3<T> gu = (c * ds_du - s * w) / r, gw = (c * ds_dw - s * u) / r;
  return {V3<T>(-(gu + gw)), gu, gw};
}

// The gradient of the sum over the corners of w (theta0 - theta) over the triangle's particles.
template <typename T>
std::array<V3<T>, 3> term_gradient(const std::array<double, 3>& weight,
                                   const std::array<V3<T>, 3>& x) {
  std::array<V3<T>, 3> g = {V3<T>::Zero(), V3<T>::Zero(), V3<T>::Zero()};
  for (size_t k = 0; k < 3; ++k) {
    if (weight[k] == 0.0) continue;
    const size_t a = (k + 1) % 3, b = (k + 2) % 3;
    const auto d = corner_gradient<T>(x[k], x[a], x[b]);
    g[k] -= weight[k] * d[0], g[a] -= weight[k] * d[1], g[b] -= weight[k] * d[2];
  }
  return g;
}

}  // namespace

void AngleDefects::add_mesh(const std::vector<std::array<int, 3>>& triangles,
                            const Points& reference, double cd, const std::vector<int>& on_rim) {
  std::vector<bool> rim(static_cast<size_t>(reference.cols()), false);
  for (int p : on_rim) rim[static_cast<size_t>(p)] = true;
  for (const auto& t : triangles) {
    v.push_back(t);
    std::array<double, 3> angles;
    std::array<bool, 3> inner;
    for (size_t k = 0; k < 3; ++k) {
      angles[k] = corner_angle<double>(reference.col(t[k]), reference.col(t[(k + 1) % 3]),
                                       reference.col(t[(k + 2) % 3]));
      inner[k] = !rim[static_cast<size_t>(t[k])];
    }
    const Vec3 a = reference.col(t[0]), b = reference.col(t[1]), c = reference.col(t[2]);
    rest.push_back(angles);
    interior.push_back(inner);
    weight.push_back({0.0, 0.0, 0.0});
    plate.push_back(cd);
    area.push_back(0.5 * (b - a).cross(c - a).norm());
    resin.push_back(false);
  }
  update_weights();
}

void AngleDefects::update_weights() {
  int n = 0;
  for (const auto& t : v) n = std::max({n, t[0] + 1, t[1] + 1, t[2] + 1});
  std::vector<double> cda(static_cast<size_t>(n), 0.0), a(static_cast<size_t>(n), 0.0);
  for (size_t i = 0; i < v.size(); ++i)
    for (int p : v[i])
      cda[static_cast<size_t>(p)] += plate[i] * area[i], a[static_cast<size_t>(p)] += area[i];
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      const auto p = static_cast<size_t>(v[i][k]);
      weight[i][k] = interior[i][k] && a[p] > 0.0 ? 0.5 * cda[p] / a[p] : 0.0;
    }
}

void AngleDefects::filter(const std::vector<bool>& keep) {
  keep_where(v, keep);
  keep_where(rest, keep);
  keep_where(weight, keep);
  keep_where(plate, keep);
  keep_where(area, keep);
  keep_where(resin, keep);
  keep_where(interior, keep);
}

double AngleDefects::energy(int i, const Points& x) const {
  const auto k = static_cast<size_t>(i);
  const auto& p = v[k];
  double e = 0.0;
  for (size_t c = 0; c < 3; ++c) {
    if (weight[k][c] == 0.0) continue;
    e += weight[k][c] * (rest[k][c] - corner_angle<double>(x.col(p[c]), x.col(p[(c + 1) % 3]),
                                                           x.col(p[(c + 2) % 3])));
  }
  return e;
}

void AngleDefects::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const auto k = static_cast<size_t>(i);
    if (!active(i)) continue;
    const auto& p = v[k];
    const auto g = term_gradient<double>(weight[k], {x.col(p[0]), x.col(p[1]), x.col(p[2])});
    for (size_t c = 0; c < 3; ++c) f.col(p[c]) -= g[c];
  }
}

Eigen::Matrix<double, 9, 9> AngleDefects::hessian(int i, const Points& x, bool project) const {
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 9, 1>>;
  const auto k = static_cast<size_t>(i);
  const auto& p = v[k];
  std::array<V3<Dual>, 3> y;
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d) y[static_cast<size_t>(c)][d] = Dual(x(d, p[c]), 9, 3 * c + d);
  const auto g = term_gradient<Dual>(weight[k], y);
  Eigen::Matrix<double, 9, 9> h;
  for (int r = 0; r < 9; ++r)
    h.row(r) = g[static_cast<size_t>(r / 3)][r % 3].derivatives().transpose();
  const Eigen::Matrix<double, 9, 9> sym = 0.5 * (h + h.transpose());  // not in place: aliasing
  return project ? project_psd(sym) : sym;
}

void AngleDefects::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    if (!active(i)) continue;
    const Eigen::Matrix<double, 9, 9> h = hessian(i, x, true);
    const auto& p = v[static_cast<size_t>(i)];
    for (int c = 0; c < 3; ++c) diag[p[c]] += h.block<3, 3>(3 * c, 3 * c).trace() / 3.0;
  }
}

int AngleDefects::impregnate(const Impregnation& at) {
  const double cd_resin = angle_defect_coefficient(1.0 / 3.0) * bending_stiffness(at.resin);
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    const auto& p = v[k];
    const Vec3 c = (at.x.col(p[0]) + at.x.col(p[1]) + at.x.col(p[2])) / 3.0;
    if (resin[k] || !at.pattern.contains(c.head<2>())) continue;
    plate[k] += cd_resin;
    resin[k] = true;
    ++count;
  }
  if (count > 0) update_weights();
  return count;
}

bool AngleDefects::severed(int i, const CrossesCut& crosses) const {
  const auto& p = v[static_cast<size_t>(i)];
  return crosses(p[0], p[1]) || crosses(p[1], p[2]) || crosses(p[2], p[0]);
}

void AngleDefects::carry(const AngleDefects& old, const Rebuild& r) {
  for (int i = 0; i < old.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    std::array<int, 3> p;
    if (!r.map(old.v[k], p)) continue;
    v.push_back(p);
    rest.push_back(old.rest[k]);
    interior.push_back(old.interior[k]);
    weight.push_back(old.weight[k]);
    plate.push_back(old.plate[k]);
    area.push_back(old.area[k]);
    resin.push_back(old.resin[k]);
  }
  update_weights();  // a particle that lost triangles averages over those left
}

}  // namespace membra
