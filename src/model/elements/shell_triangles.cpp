#include "membra/model/elements/shell_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

#include <Eigen/Dense>

#include "membra/core/second_order.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"

namespace membra {

static_assert(ElementSet<ShellTriangles>);

namespace {

template <typename T>
using M2 = Eigen::Matrix<T, 2, 2>;
using Grad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;
using Jet = SecondOrder<9>;

// The plates' bilinear form: sum over layers of A (D/2) [nu tr(Ma) tr(Mb) + (1 - nu) tr(Ma Mb)],
// M = G^-1 X; the energy is Q(II, II).
double plate_form(const std::array<const PlateLayer*, 2>& layers, const Eigen::Matrix2d& a,
                  const Eigen::Matrix2d& b) {
  double q = 0.0;
  for (const PlateLayer* l : layers) {
    if (!(l->area > 0.0) || l->d == 0.0) continue;
    const Eigen::Matrix2d ga = l->metric_inverse * a, gb = l->metric_inverse * b;
    q += 0.5 * l->area * l->d *
         (l->nu * ga.trace() * gb.trace() + (1.0 - l->nu) * (ga * gb).trace());
  }
  return q;
}

// The weight of the mid-edge estimate against the fit's rows (which are O(1)): small enough to
// move a well-posed fit by well under 1 %, large enough to bound a degenerate one.
constexpr double kPrior = 1e-3;

// A 3-vector of any scalar (double, first- or second-order duals) with the few operations the
// curvature scalars need.
template <typename T>
struct P3 {
  T x, y, z;
  T& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
};
template <typename T>
P3<T> operator-(const P3<T>& a, const P3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T>
P3<T> operator+(const P3<T>& a, const P3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
P3<T> scaled(const P3<T>& a, const T& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <typename T>
T dot(const P3<T>& a, const P3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
P3<T> cross(const P3<T>& a, const P3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double value_of(double a) {
  return a;
}
double value_of(const Grad& a) {
  return a.value();
}
double value_of(const Jet& a) {
  return a.v;
}

// The six geometric scalars a triangle's curvature is read from, each of its three corners and
// one far corner p3 (edge k lies opposite corner k): m < 3, the far corner's height over the
// face's plane; m >= 3, the mid-edge reading of edge k = m - 3, s_k = (x_{k+1} + x_{k+2} - 2 x_k)
// . m_k / |m_k|, m_k the mean of the face's and the neighbour's (x_{k+2}, x_{k+1}, p3) normals.
template <typename T>
T geometric(int m, const std::array<P3<T>, 4>& p) {
  using std::sqrt;
  const P3<T> c = cross(p[1] - p[0], p[2] - p[0]);
  // A face collapsed to a line has no normal: no reading (as a zero normal read before).
  if (!(value_of(dot(c, c)) > 0.0)) return T(0.0);
  const T c_norm = sqrt(dot(c, c));
  if (m < 3) return dot(p[3] - p[0], c) / c_norm;
  const auto k = static_cast<size_t>(m - 3);
  const P3<T>&a = p[(k + 1) % 3], &b = p[(k + 2) % 3];
  const P3<T> c2 = cross(a - b, p[3] - b);
  if (!(value_of(dot(c2, c2)) > 0.0)) return T(0.0);
  const T inv_c = T(1.0) / c_norm, inv_c2 = T(1.0) / T(sqrt(dot(c2, c2)));
  const P3<T> mk = scaled(c, inv_c) + scaled(c2, inv_c2);
  const T mk2 = dot(mk, mk);
  // A neighbour folded flat onto the face has no mean normal: no reading (its weight is small).
  if (value_of(mk2) < 1e-12) return T(0.0);
  const P3<T> twice{p[k].x * T(2.0), p[k].y * T(2.0), p[k].z * T(2.0)};
  return dot(a + b - twice, mk) / sqrt(mk2);
}

// The stencil position (0..17) of local coordinate c (0..11) of scalar m's four points.
int stencil_dof(int m, int c) {
  return c < 9 ? c : 9 + 3 * (m % 3) + (c - 9);
}

}  // namespace

// The linear map from the six scalars to the curvature H = (H11, H12, H22) in the edge
// coordinates, and the plates' quadratic form on H (E = H^T Q H). The second fundamental form is
// the Hessian of the quadratic that vanishes at the corners, (H11 u^2 + 2 H12 uv + H22 v^2 -
// H11 u - H22 v) / 2, and meets each far corner's height: row k of the fit (its (u, v) on the
// natural sheet). A free edge (on the rim, or against a much softer neighbour) has no height to
// meet; its row asks instead that the moment across it vanish, the plate's condition at a free
// edge: dE/dII : (c c^T) = 0, c the edge's conormal in (u, v) (metric-free: it annihilates the
// edge's direction). Across a resin edge this leaves the kink to the latex, as plates in series
// share it. (Minimizing the energy over the free height instead also relaxes curvature along the
// edge: a strip then buckled 9 % below Euler's load.) The rows are solved by least squares with
// a weak pull (kPrior) towards the mid-edge estimate H11 = -(s0 + s1), H12 = -s0,
// H22 = -(s0 + s2) (exact on symmetric neighbours only), which fills in what the fit cannot see.
// The fit is singular where all six points lie on one conic, e.g. at an interior corner of three
// triangles, whose two neighbours share their far corner (two equal rows); the pull bounds the gain
// from heights to curvature (at most 1/(2 sqrt kPrior), about 16) and moves a well-posed fit by
// about kPrior / sigma_min^2 of its gap to the mid-edge estimate (0.4 % on the best-conditioned
// stencils). A free edge's mid-edge reading is left out (the estimate then takes s_k = 0).
ShellTriangles::Plan ShellTriangles::plan(int i) const {
  const auto k0 = static_cast<size_t>(i);
  Plan out;
  out.free = free_edges(i);
  const std::array<const PlateLayer*, 2> layers{&latex[k0], &resin[k0]};
  static const std::array<Eigen::Matrix2d, 3> unit{(Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 1, 1, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 0, 0, 1).finished()};
  static const std::array<Eigen::Matrix2d, 3> conormal{
      (Eigen::Matrix2d() << 1, 1, 1, 1).finished(), (Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
      (Eigen::Matrix2d() << 0, 0, 0, 1).finished()};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out.form(r, c) =
          plate_form(layers, unit[static_cast<size_t>(r)], unit[static_cast<size_t>(c)]);
  Eigen::Matrix3d a;
  for (size_t k = 0; k < 3; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    if (!out.free[k]) {
      a.row(row) = fit[k0][k].transpose();
      continue;
    }
    Eigen::RowVector3d moment;
    for (size_t j = 0; j < 3; ++j)
      moment[static_cast<Eigen::Index>(j)] = plate_form(layers, conormal[k], unit[j]);
    a.row(row) = moment / std::max(moment.norm(), 1e-300);
  }
  const Eigen::Matrix3d solve =
      (a.transpose() * a + kPrior * Eigen::Matrix3d::Identity()).inverse();
  Eigen::Matrix<double, 3, 6> scalars = Eigen::Matrix<double, 3, 6>::Zero();
  for (int k = 0; k < 3; ++k)
    if (!out.free[static_cast<size_t>(k)]) scalars.col(k) = a.row(k).transpose();
  Eigen::Matrix3d mid;  // (H11, H12, H22) from (s0, s1, s2)
  mid << -1, -1, 0, -1, 0, 0, -1, 0, -1;
  for (int k = 0; k < 3; ++k)
    if (!out.free[static_cast<size_t>(k)]) scalars.col(3 + k) = kPrior * mid.col(k);
  out.map = solve * scalars;
  return out;
}

namespace {

PlateLayer plate_at(const Eigen::Matrix2d& metric, double d, double nu) {
  const double det = metric.determinant();
  if (!(det > 0.0)) throw std::invalid_argument("shell triangle: degenerate rest shape");
  return {metric.inverse(), 0.5 * std::sqrt(det), d, nu};
}

Eigen::Matrix2d metric_of(const Points& x, const std::array<int, 6>& p) {
  return triangle_metric(x.col(p[0]), x.col(p[1]), x.col(p[2]));
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
  const Plan pl = plan(i);
  Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
  for (int m = 0; m < 6; ++m) {
    if (pl.free[static_cast<size_t>(m % 3)]) continue;
    std::array<P3<double>, 4> q;
    for (size_t j = 0; j < 4; ++j) {
      const auto col = x.col(j < 3 ? p[j] : p[3 + static_cast<size_t>(m % 3)]);
      q[j] = {col.x(), col.y(), col.z()};
    }
    g[m] = geometric(m, q);
  }
  const Eigen::Vector3d h = pl.map * g;
  return h.dot(pl.form * h);
}

// The scalars' values and gradients (6 x 18), and with `second` each one's Hessian (12 x 12 over
// its four points), by first- or second-order dual numbers over 12 coordinates.
struct ShellScalars {
  Eigen::Matrix<double, 6, 1> value = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 18> gradient = Eigen::Matrix<double, 6, 18>::Zero();
  std::array<Eigen::Matrix<double, 12, 12>, 6> hessian{};
};

void ShellTriangles::scalars(int i, const Points& x, const Plan& pl, bool second,
                             ShellScalars& out) const {
  const auto& p = v[static_cast<size_t>(i)];
  for (int m = 0; m < 6; ++m) {
    if (pl.free[static_cast<size_t>(m % 3)]) continue;
    const std::array<int, 4> pts{p[0], p[1], p[2], p[3 + m % 3]};
    if (!second) {
      std::array<P3<Grad>, 4> q;
      for (int c = 0; c < 12; ++c)
        q[static_cast<size_t>(c / 3)][c % 3] =
            Grad(x(c % 3, pts[static_cast<size_t>(c / 3)]), 12, c);
      const Grad g = geometric(m, q);
      out.value[m] = g.value();
      for (int c = 0; c < 12; ++c) out.gradient(m, stencil_dof(m, c)) += g.derivatives()[c];
      continue;
    }
    // The scalars depend on differences only: differentiate over p1 - p0, p2 - p0, p3 - p0 (9
    // variables, not 12) and map back with d = L x.
    std::array<P3<Jet>, 4> q{P3<Jet>{Jet(0.0), Jet(0.0), Jet(0.0)}};
    for (int c = 0; c < 9; ++c)
      q[static_cast<size_t>(1 + c / 3)][c % 3] =
          Jet::variable(x(c % 3, pts[static_cast<size_t>(1 + c / 3)]) - x(c % 3, pts[0]), c);
    const Jet g = geometric(m, q);
    static const Eigen::Matrix<double, 9, 12> diff = [] {
      Eigen::Matrix<double, 9, 12> l = Eigen::Matrix<double, 9, 12>::Zero();
      for (int j = 0; j < 3; ++j) {
        l.block<3, 3>(3 * j, 0) = -Eigen::Matrix3d::Identity();
        l.block<3, 3>(3 * j, 3 * (j + 1)) = Eigen::Matrix3d::Identity();
      }
      return l;
    }();
    out.value[m] = g.v;
    const Eigen::Matrix<double, 12, 1> grad = diff.transpose() * g.g;
    for (int c = 0; c < 12; ++c) out.gradient(m, stencil_dof(m, c)) += grad[c];
    out.hessian[static_cast<size_t>(m)] = diff.transpose() * g.h * diff;
  }
}

void ShellTriangles::add_forces(const Points& x, const Points*, int begin, int end,
                                Points& f) const {
  ShellScalars sc;
  for (int i = begin; i < end; ++i) {
    if (!active(i)) continue;
    const Plan pl = plan(i);
    sc.value.setZero();
    sc.gradient.setZero();
    scalars(i, x, pl, false, sc);
    // E = h^T Q h, h = L g: dE/dx = 2 (Q h)^T L dg/dx.
    const Eigen::Matrix<double, 6, 1> de_dg =
        2.0 * pl.map.transpose() * (pl.form * (pl.map * sc.value));
    const Eigen::Matrix<double, 18, 1> grad = sc.gradient.transpose() * de_dg;
    const auto& p = v[static_cast<size_t>(i)];
    for (int c = 0; c < 6; ++c) f.col(p[c]) -= grad.segment<3>(3 * c);
  }
}

Eigen::Matrix<double, 18, 18> ShellTriangles::hessian(int i, const Points& x, bool project) const {
  const Plan pl = plan(i);
  ShellScalars sc;
  scalars(i, x, pl, true, sc);
  // 2 (L dg)^T Q (L dg) + sum_m dE/dg_m Hess g_m.
  const Eigen::Matrix<double, 3, 18> jh = pl.map * sc.gradient;
  Eigen::Matrix<double, 18, 18> out = 2.0 * jh.transpose() * pl.form * jh;
  const Eigen::Matrix<double, 6, 1> de_dg =
      2.0 * pl.map.transpose() * (pl.form * (pl.map * sc.value));
  for (int m = 0; m < 6; ++m) {
    if (pl.free[static_cast<size_t>(m % 3)] || de_dg[m] == 0.0) continue;
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 12; ++c)
        out(stencil_dof(m, r), stencil_dof(m, c)) +=
            de_dg[m] * sc.hessian[static_cast<size_t>(m)](r, c);
  }
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
    const PlateLayer old = latex[k];
    latex[k] =
        plate_at(released_metric(natural_metric[k], frame_metric[k], release), old.d, old.nu);
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
    if (!pattern_covers(at, p[0], p[1], p[2]))
      continue;  // a later coat replaces, as the membrane's
    resin[k] = plate_at(metric_of(at.x, p), d, 1.0 / 3.0);
    ++count;
  }
  return count;
}

void ShellTriangles::grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
                          const ReleaseLevel& release) {
  for (size_t k = 0; k < v.size(); ++k) {
    if (g[k].none()) continue;
    latex[k].area *= grow_metrics(g[k], paper, v[k][0], v[k][1], v[k][2], exponent,
                                  natural_metric[k], frame_metric[k]);
  }
  update(release);
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
