#include "membra/model/elements/shell_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

#include <Eigen/Dense>

#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"

namespace membra {

static_assert(ElementSet<ShellTriangles>);

namespace {

template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using M2 = Eigen::Matrix<T, 2, 2>;
using Grad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 18, 1>>;
using Hess = Eigen::AutoDiffScalar<Eigen::Matrix<Grad, 18, 1>>;

// The plates' bilinear form: sum over layers of A (D/2) [nu tr(Ma) tr(Mb) + (1 - nu) tr(Ma Mb)],
// M = G^-1 X; the energy is Q(II, II).
template <typename T>
T plate_form(const std::array<const PlateLayer*, 2>& layers, const M2<T>& a, const M2<T>& b) {
  T q(0.0);
  for (const PlateLayer* l : layers) {
    if (!(l->area > 0.0) || l->d == 0.0) continue;
    const M2<T> ga = l->metric_inverse.cast<T>() * a, gb = l->metric_inverse.cast<T>() * b;
    q += T(0.5 * l->area * l->d) *
         (T(l->nu) * ga.trace() * gb.trace() + T(1.0 - l->nu) * (ga * gb).trace());
  }
  return q;
}

// The second fundamental form II (edge coordinates u, v of p = x0 + u e1 + v e2) is the Hessian
// H of the quadratic that vanishes at the corners, q = (H11 u^2 + 2 H12 uv + H22 v^2 - H11 u -
// H22 v) / 2, and meets each far corner's height over the face's plane: row k of the fit (its
// (u, v) on the natural sheet). A free edge (on the rim, or against a much softer neighbour)
// has no height to meet; its row asks instead that the moment across it vanish, the plate's
// condition at a free edge: dE/dII : (c c^T) = 0, c the edge's conormal in (u, v) (metric-free:
// it annihilates the edge's direction). Across a resin edge this leaves the kink to the latex,
// as plates in series share it. (Minimizing the energy over the free height instead also relaxes
// curvature along the edge: a strip then buckled 9 % below Euler's load.) The 3 x 3 system
// depends on the rest state only; its pseudo-inverse keeps a degenerate fit finite.
template <typename T>
T stencil_energy(const ShellTriangles& s, int i, const std::array<V3<T>, 6>& q) {
  const auto k0 = static_cast<size_t>(i);
  const std::array<bool, 3> free = s.free_edges(i);
  const std::array<const PlateLayer*, 2> layers{&s.latex[k0], &s.resin[k0]};
  static const std::array<Eigen::Matrix2d, 3> unit{(Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 1, 1, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 0, 0, 1).finished()};
  static const std::array<Eigen::Matrix2d, 3> conormal{
      (Eigen::Matrix2d() << 1, 1, 1, 1).finished(), (Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
      (Eigen::Matrix2d() << 0, 0, 0, 1).finished()};
  Eigen::Matrix3d a;
  for (size_t k = 0; k < 3; ++k) {
    if (!free[k]) {
      a.row(static_cast<Eigen::Index>(k)) = s.fit[k0][k].transpose();
      continue;
    }
    Eigen::RowVector3d row;
    for (size_t j = 0; j < 3; ++j)
      row[static_cast<Eigen::Index>(j)] = plate_form<double>(layers, conormal[k], unit[j]);
    a.row(static_cast<Eigen::Index>(k)) = row / std::max(row.norm(), 1e-300);
  }
  const Eigen::Matrix3d inv = a.completeOrthogonalDecomposition().pseudoInverse();
  const V3<T> n = (q[1] - q[0]).cross(q[2] - q[0]).normalized();
  std::array<T, 3> height;
  for (size_t k = 0; k < 3; ++k) height[k] = free[k] ? T(0.0) : (q[3 + k] - q[0]).dot(n);
  M2<T> ii = M2<T>::Constant(T(0.0));
  for (size_t j = 0; j < 3; ++j) {
    T h(0.0);
    for (size_t k = 0; k < 3; ++k)
      if (!free[k])
        h += T(inv(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k))) * height[k];
    ii += unit[j].cast<T>() * h;
  }
  return plate_form(layers, ii, ii);
}

PlateLayer plate_at(const Eigen::Matrix2d& metric, double d, double nu) {
  const double det = metric.determinant();
  if (!(det > 0.0)) throw std::invalid_argument("shell triangle: degenerate rest shape");
  return {metric.inverse(), 0.5 * std::sqrt(det), d, nu};
}

Eigen::Matrix2d metric_of(const Points& x, const std::array<int, 6>& p) {
  Eigen::Matrix<double, 3, 2> ds;
  ds.col(0) = x.col(p[1]) - x.col(p[0]);
  ds.col(1) = x.col(p[2]) - x.col(p[0]);
  return ds.transpose() * ds;
}

}  // namespace

void ShellTriangles::add_mesh(const std::vector<std::array<int, 3>>& triangles,
                              const Points& reference, double d, double nu) {
  if (!(d >= 0.0) || !(nu >= 0.0 && nu < 1.0))
    throw std::invalid_argument("shell triangles: a negative stiffness or nu outside [0, 1)");
  // Each directed edge (a, b) with its triangle; the neighbour across it holds (b, a).
  std::map<std::pair<int, int>, int> owner;
  const int first = size();
  for (size_t t = 0; t < triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k)
      owner[{triangles[t][k], triangles[t][(k + 1) % 3]}] = first + static_cast<int>(t);
  for (const auto& t : triangles) {
    std::array<int, 6> ids{t[0], t[1], t[2], t[0], t[1], t[2]};
    std::array<int, 3> across{-1, -1, -1};
    for (size_t k = 0; k < 3; ++k) {
      const auto o = owner.find({t[(k + 2) % 3], t[(k + 1) % 3]});
      if (o == owner.end()) continue;
      across[k] = o->second;
      const auto& u = triangles[static_cast<size_t>(o->second - first)];
      for (int c : u)
        if (c != t[(k + 1) % 3] && c != t[(k + 2) % 3]) ids[3 + k] = c;
    }
    const Eigen::Matrix2d g = metric_of(reference, ids);
    latex.push_back(plate_at(g, d, nu));
    // Each far corner's row of the fit: (u^2 - u, 2 uv, v^2 - v) / 2 at its (u, v).
    Eigen::Matrix2d e;
    e << (reference.col(t[1]) - reference.col(t[0])).head<2>(),
        (reference.col(t[2]) - reference.col(t[0])).head<2>();
    const Eigen::Matrix2d e_inv = e.inverse();
    std::array<Eigen::Vector3d, 3> rows;
    for (size_t k = 0; k < 3; ++k) {
      const Vec2 uv = e_inv * (reference.col(ids[3 + k]) - reference.col(t[0])).head<2>();
      rows[k] = Eigen::Vector3d(0.5 * (uv.x() * uv.x() - uv.x()), uv.x() * uv.y(),
                                0.5 * (uv.y() * uv.y() - uv.y()));
    }
    fit.push_back(rows);
    resin.emplace_back();
    v.push_back(ids);
    neighbour.push_back(across);
    natural_metric.push_back(g);
    frame_metric.push_back(g);
  }
}

void ShellTriangles::filter(const std::vector<bool>& keep) {
  // The survivors' new indices: a neighbour removed leaves a free edge.
  std::vector<int> renumber(keep.size(), -1);
  int next = 0;
  for (size_t k = 0; k < keep.size(); ++k)
    if (keep[k]) renumber[k] = next++;
  for (size_t t = 0; t < v.size(); ++t)
    for (size_t k = 0; k < 3; ++k) {
      int& o = neighbour[t][k];
      if (o >= 0) o = renumber[static_cast<size_t>(o)];
      if (o < 0) v[t][3 + k] = v[t][k];
    }
  keep_where(v, keep);
  keep_where(neighbour, keep);
  keep_where(fit, keep);
  keep_where(latex, keep);
  keep_where(resin, keep);
  keep_where(natural_metric, keep);
  keep_where(frame_metric, keep);
}

double ShellTriangles::plate(int i) const {
  return latex[static_cast<size_t>(i)].d + resin[static_cast<size_t>(i)].d;
}

std::array<bool, 3> ShellTriangles::free_edges(int i) const {
  const auto k0 = static_cast<size_t>(i);
  std::array<bool, 3> free{};
  for (size_t k = 0; k < 3; ++k) {
    const int o = neighbour[k0][k];
    free[k] = o < 0 || plate(o) < kSofter * plate(i);
  }
  return free;
}

double ShellTriangles::energy(int i, const Points& x) const {
  const auto& p = v[static_cast<size_t>(i)];
  std::array<V3<double>, 6> q;
  for (size_t c = 0; c < 6; ++c) q[c] = x.col(p[c]);
  return stencil_energy(*this, i, q);
}

void ShellTriangles::add_forces(const Points& x, const Points*, int begin, int end,
                                Points& f) const {
  for (int i = begin; i < end; ++i) {
    if (!active(i)) continue;
    const auto& p = v[static_cast<size_t>(i)];
    std::array<V3<Grad>, 6> q;
    for (int c = 0; c < 6; ++c)
      for (int r = 0; r < 3; ++r) q[static_cast<size_t>(c)][r] = Grad(x(r, p[c]), 18, 3 * c + r);
    const Grad e = stencil_energy(*this, i, q);
    for (int c = 0; c < 6; ++c) f.col(p[c]) -= e.derivatives().segment<3>(3 * c);
  }
}

Eigen::Matrix<double, 18, 18> ShellTriangles::hessian(int i, const Points& x, bool project) const {
  const auto& p = v[static_cast<size_t>(i)];
  std::array<V3<Hess>, 6> q;
  for (int c = 0; c < 6; ++c)
    for (int r = 0; r < 3; ++r) {
      const int k = 3 * c + r;
      Hess& h = q[static_cast<size_t>(c)][r];
      h.value() = Grad(x(r, p[c]), 18, k);
      h.derivatives() = Eigen::Matrix<Grad, 18, 1>::Constant(Grad(0.0));
      h.derivatives()[k] = Grad(1.0);
      for (int j = 0; j < 18; ++j) h.derivatives()[j].derivatives().setZero();
    }
  const Hess e = stencil_energy(*this, i, q);
  Eigen::Matrix<double, 18, 18> out;
  for (int r = 0; r < 18; ++r) out.row(r) = e.derivatives()[r].derivatives().transpose();
  const Eigen::Matrix<double, 18, 18> sym = 0.5 * (out + out.transpose());
  return project ? project_psd(sym) : sym;
}

void ShellTriangles::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    if (!active(i)) continue;
    const Eigen::Matrix<double, 18, 18> h = hessian(i, x, true);
    const auto& p = v[static_cast<size_t>(i)];
    for (int c = 0; c < 6; ++c) diag[p[c]] += h.block<3, 3>(3 * c, 3 * c).trace() / 3.0;
  }
}

void ShellTriangles::update(const ReleaseLevel& release) {
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    const Eigen::Matrix2d g =
        release.releasing ? Eigen::Matrix2d(natural_metric[k] +
                                            release.level * (frame_metric[k] - natural_metric[k]))
                          : natural_metric[k];
    const PlateLayer old = latex[k];
    latex[k] = plate_at(g, old.d, old.nu);
    latex[k].area = old.area;  // the material's area: its plate does not grow with the metric
  }
}

void ShellTriangles::begin_release(const Points& x) {
  for (int i = 0; i < size(); ++i) frame_metric[static_cast<size_t>(i)] = metric_of(x, ids(i));
}

int ShellTriangles::impregnate(const Impregnation& at) {
  const double d = bending_stiffness(at.resin);
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    const auto& p = v[k];
    const Vec3 c = (at.x.col(p[0]) + at.x.col(p[1]) + at.x.col(p[2])) / 3.0;
    if (resin[k].area > 0.0 || !at.pattern.contains(c.head<2>())) continue;
    resin[k] = plate_at(metric_of(at.x, p), d, 1.0 / 3.0);
    ++count;
  }
  return count;
}

bool ShellTriangles::severed(int i, const CrossesCut& crosses) const {
  const auto& p = v[static_cast<size_t>(i)];
  return crosses(p[0], p[1]) || crosses(p[1], p[2]) || crosses(p[2], p[0]);
}

void ShellTriangles::carry(const ShellTriangles& old, const Rebuild& r) {
  // The carried triangles' new indices, then their neighbours renumbered (a lost one: free edge).
  std::vector<int> renumber(static_cast<size_t>(old.size()), -1);
  const int first = size();
  for (int i = 0; i < old.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    std::array<int, 3> corners{old.v[k][0], old.v[k][1], old.v[k][2]}, mapped;
    if (!r.map(corners, mapped)) continue;
    renumber[k] = size();
    std::array<int, 6> ids{mapped[0], mapped[1], mapped[2], mapped[0], mapped[1], mapped[2]};
    for (size_t c = 0; c < 3; ++c) {
      const int far = r.new_of_old[static_cast<size_t>(old.v[k][3 + c])];
      if (old.neighbour[k][c] >= 0 && far >= 0) ids[3 + c] = far;
    }
    v.push_back(ids);
    neighbour.push_back(old.neighbour[k]);
    fit.push_back(old.fit[k]);
    latex.push_back(old.latex[k]);
    resin.push_back(old.resin[k]);
    natural_metric.push_back(old.natural_metric[k]);
    frame_metric.push_back(old.frame_metric[k]);
  }
  for (size_t t = static_cast<size_t>(first); t < v.size(); ++t)
    for (size_t c = 0; c < 3; ++c) {
      int& o = neighbour[t][c];
      if (o >= 0) o = renumber[static_cast<size_t>(o)];
      if (o < 0) v[t][3 + c] = v[t][c];
    }
}

}  // namespace membra
