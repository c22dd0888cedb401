#include "membra/model/elements/membrane_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>

#include <Eigen/Eigenvalues>

#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<MembraneTriangles>);

namespace {

template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;

// The layer's energy gradient dE/dDs (3 x 2, columns for x1 and x2) at the current edges Ds:
// E = V W(I, J), dI/dDs = 2 Ds G^-1, dJ/dDs = 2 Ds adj(g) / det G.
template <typename T>
Eigen::Matrix<T, 3, 2> layer_gradient(const LayerRest& r, const Eigen::Matrix<T, 3, 2>& ds) {
  const Eigen::Matrix<T, 2, 2> g = ds.transpose() * ds;
  const T i = (r.metric_inverse.cast<T>() * g).trace();
  const T j = (g(0, 0) * g(1, 1) - g(0, 1) * g(1, 0)) * r.inverse_det;
  const LawValue<T> w = strain_energy(r.law, i, j);
  Eigen::Matrix<T, 2, 2> adj;
  adj << g(1, 1), -g(0, 1), -g(1, 0), g(0, 0);
  const Eigen::Matrix<T, 2, 2> m =
      (2.0 * r.volume) * (w.w_i * r.metric_inverse.cast<T>() + (w.w_j * r.inverse_det) * adj);
  return ds * m;
}

template <typename T>
Eigen::Matrix<T, 3, 2> edges(const V3<T>& x0, const V3<T>& x1, const V3<T>& x2) {
  Eigen::Matrix<T, 3, 2> ds;
  ds.col(0) = x1 - x0;
  ds.col(1) = x2 - x0;
  return ds;
}

// Both layers' gradient over (x0, x1, x2).
template <typename T>
std::array<V3<T>, 3> triangle_gradient(const LayerRest& latex, const LayerRest& resin,
                                       const V3<T>& x0, const V3<T>& x1, const V3<T>& x2) {
  const Eigen::Matrix<T, 3, 2> ds = edges(x0, x1, x2);
  Eigen::Matrix<T, 3, 2> h = layer_gradient(latex, ds);
  if (resin.volume > 0.0) h += layer_gradient(resin, ds);
  return {V3<T>(-(h.col(0) + h.col(1))), V3<T>(h.col(0)), V3<T>(h.col(1))};
}

double layer_energy(const LayerRest& r, const Eigen::Matrix2d& g) {
  if (!(r.volume > 0.0)) return 0.0;
  const double i = (r.metric_inverse * g).trace(), j = g.determinant() * r.inverse_det;
  return r.volume * strain_energy(r.law, i, j).w;
}

LayerRest layer_at(const Eigen::Matrix2d& metric, double volume, const LawConstants& law) {
  const double det = metric.determinant();
  if (!(det > 0.0)) throw std::invalid_argument("membrane triangle: degenerate rest shape");
  return {metric.inverse(), 1.0 / det, volume, law};
}

}  // namespace

Eigen::Matrix2d triangle_metric(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
  const Eigen::Matrix<double, 3, 2> ds = edges<double>(x0, x1, x2);
  return ds.transpose() * ds;
}

Eigen::Matrix2d released_metric(const Eigen::Matrix2d& natural, const Eigen::Matrix2d& frame,
                                const ReleaseLevel& release) {
  return release.releasing ? Eigen::Matrix2d(natural + release.level * (frame - natural)) : natural;
}

bool triangle_severed(const CrossesCut& crosses, int a, int b, int c) {
  return crosses(a, b) || crosses(b, c) || crosses(c, a);
}

bool pattern_covers(const Impregnation& at, int a, int b, int c) {
  const Vec3 centroid = (at.x.col(a) + at.x.col(b) + at.x.col(c)) / 3.0;
  return at.pattern.contains(centroid.head<2>());
}

LocalGrowth triangle_growth(const GrowthField& field, const Points& paper, int a, int b, int c) {
  const std::array<int, 3> id = {a, b, c};
  const std::array<Vec2, 3> p = {paper.col(a).head<2>(), paper.col(b).head<2>(),
                                 paper.col(c).head<2>()};
  return field.at(id, p, "triangle");
}

double grow_metrics(const LocalGrowth& g, const Points& paper, int a, int b, int c, double exponent,
                    Eigen::Matrix2d& natural, Eigen::Matrix2d& frame) {
  Eigen::Matrix2d e;
  e << paper.col(b).head<2>() - paper.col(a).head<2>(),
      paper.col(c).head<2>() - paper.col(a).head<2>();
  const Eigen::Matrix2d s = e.inverse() * g.stretch(exponent) * e;
  natural = s.transpose() * natural * s;
  frame = s.transpose() * frame * s;
  return std::abs(s.determinant());
}

void MembraneTriangles::add(const std::array<int, 3>& ids, const Vec3& p0, const Vec3& p1,
                            const Vec3& p2, const LawConstants& law, double t) {
  if (!(t > 0.0)) throw std::invalid_argument("membrane triangle: thickness must be positive");
  const Eigen::Matrix2d g = triangle_metric(p0, p1, p2);
  const double area = 0.5 * std::sqrt(std::max(0.0, g.determinant()));
  latex.push_back(layer_at(g, area * t, law));
  resin.emplace_back();
  v.push_back(ids);
  natural_metric.push_back(g);
  frame_metric.push_back(g);
  thickness.push_back(t);
}

void MembraneTriangles::filter(const std::vector<bool>& keep) {
  keep_where(v, keep);
  keep_where(latex, keep);
  keep_where(resin, keep);
  keep_where(natural_metric, keep);
  keep_where(frame_metric, keep);
  keep_where(thickness, keep);
}

double MembraneTriangles::energy(int i, const Points& x) const {
  const auto& p = v[static_cast<size_t>(i)];
  const Eigen::Matrix2d g = triangle_metric(x.col(p[0]), x.col(p[1]), x.col(p[2]));
  return layer_energy(latex[static_cast<size_t>(i)], g) +
         layer_energy(resin[static_cast<size_t>(i)], g);
}

void MembraneTriangles::add_forces(const Points& x, const Points*, int begin, int end,
                                   Points& f) const {
  for (int i = begin; i < end; ++i) {
    const auto& p = v[static_cast<size_t>(i)];
    const auto g =
        triangle_gradient<double>(latex[static_cast<size_t>(i)], resin[static_cast<size_t>(i)],
                                  x.col(p[0]), x.col(p[1]), x.col(p[2]));
    for (int k = 0; k < 3; ++k) f.col(p[k]) -= g[static_cast<size_t>(k)];
  }
}

Eigen::Matrix<double, 9, 9> MembraneTriangles::hessian(int i, const Points& x, bool project) const {
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 9, 1>>;
  const auto& p = v[static_cast<size_t>(i)];
  std::array<V3<Dual>, 3> y;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) y[static_cast<size_t>(k)][c] = Dual(x(c, p[k]), 9, 3 * k + c);
  const auto g = triangle_gradient<Dual>(latex[static_cast<size_t>(i)],
                                         resin[static_cast<size_t>(i)], y[0], y[1], y[2]);
  Eigen::Matrix<double, 9, 9> h;
  for (int r = 0; r < 9; ++r)
    h.row(r) = g[static_cast<size_t>(r / 3)][r % 3].derivatives().transpose();
  const Eigen::Matrix<double, 9, 9> sym = 0.5 * (h + h.transpose());  // not in place: aliasing
  return project ? project_psd(sym) : sym;
}

void MembraneTriangles::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    const Eigen::Matrix<double, 9, 9> h = hessian(i, x, true);
    const auto& p = v[static_cast<size_t>(i)];
    for (int k = 0; k < 3; ++k) diag[p[k]] += h.block<3, 3>(3 * k, 3 * k).trace() / 3.0;
  }
}

namespace {

// Triangle i's symmetric membrane force tensor (N/m) and an orthonormal basis of its plane;
// false for a triangle collapsed to a line.
bool force_tensor(const MembraneTriangles& t, int i, const Points& x, Eigen::Matrix3d& n_sym,
                  Eigen::Matrix<double, 3, 2>& plane) {
  const auto& p = t.v[static_cast<size_t>(i)];
  const auto g =
      triangle_gradient<double>(t.latex[static_cast<size_t>(i)], t.resin[static_cast<size_t>(i)],
                                x.col(p[0]), x.col(p[1]), x.col(p[2]));
  const Eigen::Matrix<double, 3, 2> ds = edges<double>(x.col(p[0]), x.col(p[1]), x.col(p[2]));
  const double area = 0.5 * ds.col(0).cross(ds.col(1)).norm();
  if (!(area > 0.0)) return false;
  Eigen::Matrix<double, 3, 2> h;
  h << g[1], g[2];
  // Virtual work dE = H : dDs = a n : L for an in-plane velocity gradient L (dDs = L Ds): the
  // membrane force tensor n = H Ds^T / a (N/m), read in the triangle's plane (so that
  // compression reads negative, not as the normal's zero).
  const Eigen::Matrix3d n = h * ds.transpose() / area;
  plane.col(0) = ds.col(0).normalized();
  plane.col(1) = (ds.col(1) - ds.col(1).dot(plane.col(0)) * plane.col(0)).normalized();
  n_sym = 0.5 * (n + n.transpose());
  return true;
}

}  // namespace

Eigen::Matrix3d MembraneTriangles::stress_tensor(int i, const Points& x) const {
  Eigen::Matrix3d n;
  Eigen::Matrix<double, 3, 2> plane;
  if (!force_tensor(*this, i, x, n, plane)) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix2d n2 = plane.transpose() * n * plane;
  return plane * n2 * plane.transpose() / thickness[static_cast<size_t>(i)];
}

ElementStress MembraneTriangles::stress(int i, const Points& x, double) const {
  Eigen::Matrix3d n;
  Eigen::Matrix<double, 3, 2> plane;
  if (!force_tensor(*this, i, x, n, plane)) return {};
  const Eigen::Matrix2d n2 = plane.transpose() * n * plane;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(n2, Eigen::EigenvaluesOnly);
  ElementStress e;
  e.carries = true;
  e.stress = eig.eigenvalues().maxCoeff() / thickness[static_cast<size_t>(i)];
  // The latex's largest principal stretch: the square root of G^-1 g's largest eigenvalue.
  const auto& p = v[static_cast<size_t>(i)];
  const Eigen::Matrix<double, 3, 2> ds = edges<double>(x.col(p[0]), x.col(p[1]), x.col(p[2]));
  const Eigen::Matrix2d c = latex[static_cast<size_t>(i)].metric_inverse * (ds.transpose() * ds);
  const double mean = 0.5 * c.trace(), det = c.determinant();
  e.strained = true;
  e.strain = std::sqrt(mean + std::sqrt(std::max(0.0, mean * mean - det))) - 1.0;
  return e;
}

void MembraneTriangles::update(const ReleaseLevel& release) {
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    latex[k] = layer_at(released_metric(natural_metric[k], frame_metric[k], release),
                        latex[k].volume, latex[k].law);
  }
}

void MembraneTriangles::begin_release(const Points& x) {
  for (int i = 0; i < size(); ++i) {
    const auto& p = v[static_cast<size_t>(i)];
    frame_metric[static_cast<size_t>(i)] = triangle_metric(x.col(p[0]), x.col(p[1]), x.col(p[2]));
  }
}

int MembraneTriangles::impregnate(const Impregnation& at) {
  const LawConstants law = law_constants(at.resin.law, at.resin.youngs_modulus);
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    const auto& p = v[static_cast<size_t>(i)];
    if (!pattern_covers(at, p[0], p[1], p[2])) continue;
    const Eigen::Matrix2d g = triangle_metric(at.x.col(p[0]), at.x.col(p[1]), at.x.col(p[2]));
    const double area = 0.5 * std::sqrt(std::max(0.0, g.determinant()));
    resin[static_cast<size_t>(i)] = layer_at(g, area * at.resin.thickness, law);
    // Bonded to the resin, the latex wrinkles only as the composite does.
    latex[static_cast<size_t>(i)].law.relaxed = false;
    ++count;
  }
  return count;
}

void MembraneTriangles::grow(const std::vector<LocalGrowth>& g, const Points& paper,
                             double exponent, const ReleaseLevel& release) {
  for (size_t k = 0; k < v.size(); ++k) {
    if (g[k].none()) continue;
    // The latex grows in area, not in thickness.
    latex[k].volume *= grow_metrics(g[k], paper, v[k][0], v[k][1], v[k][2], exponent,
                                    natural_metric[k], frame_metric[k]);
  }
  update(release);
}

void MembraneTriangles::carry(const MembraneTriangles& old, const Rebuild& r) {
  for (int i = 0; i < old.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    std::array<int, 3> p;
    if (!r.map(old.v[k], p)) continue;
    v.push_back(p);
    latex.push_back(old.latex[k]);
    resin.push_back(old.resin[k]);
    natural_metric.push_back(old.natural_metric[k]);
    frame_metric.push_back(old.frame_metric[k]);
    thickness.push_back(old.thickness[k]);
  }
}

}  // namespace membra
