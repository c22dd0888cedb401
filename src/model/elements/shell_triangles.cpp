#include "membra/model/elements/shell_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "membra/model/bilayer.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/psd_projection.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<ShellTriangles>);

namespace {

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

// Below this smallest singular value (of the fit's rows, which are O(1)) a triangle's own fit is
// not used: all six points near one conic, as at an interior corner of three triangles, whose
// two neighbours share their far corner. On the mesher's meshes the smallest are about 0.1.
constexpr double kPosed = 0.05;

// The quadratic basis that vanishes at the corners, b = ((u^2 - u)/2, uv, (v^2 - v)/2), in the
// triangle's edge coordinates (u, v), and its gradient.
Eigen::Vector3d basis(const Vec2& p) {
  return {0.5 * (p.x() * p.x() - p.x()), p.x() * p.y(), 0.5 * (p.y() * p.y() - p.y())};
}
Eigen::Matrix<double, 3, 2> basis_gradient(const Vec2& p) {
  Eigen::Matrix<double, 3, 2> g;
  g << p.x() - 0.5, 0.0, p.y(), p.x(), 0.0, p.y() - 0.5;
  return g;
}

// The triangle's reading from the natural sheet: corners c (counter-clockwise) and far corners f
// (valid where `has`). The fit is the linear interpolant plus the quadratic b^T A^-1 r, r_k the
// far corner's offset from the triangle's plane extended (A's rows b at the far corners).
ShellReference reference_of(const std::array<Vec2, 3>& c, const std::array<Vec2, 3>& f,
                            const std::array<bool, 3>& has) {
  ShellReference r;
  Eigen::Matrix2d e;
  e << c[1] - c[0], c[2] - c[0];
  const double area = 0.5 * e.determinant();
  if (!(area > 0.0)) throw std::invalid_argument("shell triangle: degenerate rest shape");
  const Eigen::Matrix2d e_inv = e.inverse();
  r.gradient.col(1) = e_inv.row(0).transpose();
  r.gradient.col(2) = e_inv.row(1).transpose();
  r.gradient.col(0) = -r.gradient.col(1) - r.gradient.col(2);
  Eigen::Matrix3d rows;
  std::array<Vec2, 3> uv;
  for (size_t k = 0; k < 3; ++k) {
    uv[k] = e_inv * (f[k] - c[0]);
    rows.row(static_cast<Eigen::Index>(k)) = basis(uv[k]).transpose();
  }
  const bool all = has[0] && has[1] && has[2];
  const double sigma = all ? Eigen::JacobiSVD<Eigen::Matrix3d>(rows).singularValues()[2] : 0.0;
  r.quality = sigma >= kPosed ? sigma : 0.0;
  static const std::array<Vec2, 3> mid{Vec2(0.5, 0.5), Vec2(0.0, 0.5), Vec2(0.5, 0.0)};
  for (size_t k = 0; k < 3; ++k) {
    const Vec2 edge = c[(k + 2) % 3] - c[(k + 1) % 3];
    const double l = edge.norm();
    r.conormal[k] = Vec2(edge.y(), -edge.x()) / l;
    const Vec2 ab = e.transpose() * r.conormal[k];
    r.curvature.col(static_cast<Eigen::Index>(k)) =
        l / area * Eigen::Vector3d(ab.x() * ab.x(), ab.x() * ab.y(), ab.y() * ab.y());
    r.slope[k].head<3>() = r.conormal[k].transpose() * r.gradient;
    r.slope[k].tail<3>().setZero();
    if (r.quality == 0.0) continue;
    const Eigen::Vector3d beta =
        rows.transpose().partialPivLu().solve(basis_gradient(mid[k]) * (e_inv * r.conormal[k]));
    for (size_t j = 0; j < 3; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      r.slope[k][3 + jj] += beta[jj];
      r.slope[k][0] -= beta[jj] * (1.0 - uv[j].x() - uv[j].y());
      r.slope[k][1] -= beta[jj] * uv[j].x();
      r.slope[k][2] -= beta[jj] * uv[j].y();
    }
  }
  return r;
}

}  // namespace

std::array<ShellTriangles::Edge, 3> ShellTriangles::edges(int i) const {
  const auto k0 = static_cast<size_t>(i);
  std::array<Edge, 3> out{};
  for (size_t k = 0; k < 3; ++k) {
    const int o = neighbour[k0][k];
    if (o < 0 || plate(o) < kSofter * plate(i))
      out[k] = Edge::free;
    else if (plate(i) < kSofter * plate(o))
      out[k] = Edge::clamped;
    else
      out[k] = Edge::shared;
  }
  return out;
}

std::array<bool, 3> ShellTriangles::free_edges(int i) const {
  const std::array<Edge, 3> e = edges(i);
  return {e[0] == Edge::free, e[1] == Edge::free, e[2] == Edge::free};
}

namespace {

// A fit counts where it is posed and all three edges are shared.
bool counts(const ShellReference& r, const std::array<ShellTriangles::Edge, 3>& e) {
  using Edge = ShellTriangles::Edge;
  return r.quality > 0.0 && e[0] == Edge::shared && e[1] == Edge::shared && e[2] == Edge::shared;
}

}  // namespace

bool ShellTriangles::fit_counts(int i) const {
  return counts(reference[static_cast<size_t>(i)], edges(i));
}

int ShellTriangles::slot_of(int i, int id) const {
  const auto& p = v[static_cast<size_t>(i)];
  for (int a = 0; a < kArity; ++a)
    if (p[static_cast<size_t>(a)] == id) return a;
  return -1;
}

bool ShellTriangles::add_neighbour_slope(int i, int k, int o, double weight, Plan& pl) const {
  const auto oo = static_cast<size_t>(o);
  int facing = -1;
  for (int j = 0; j < 3; ++j)
    if (neighbour[oo][static_cast<size_t>(j)] == i) facing = j;
  if (facing < 0) return false;
  std::array<int, 6> slot{};
  for (size_t a = 0; a < 6; ++a)
    if ((slot[a] = slot_of(i, v[oo][a])) < 0) return false;
  // The neighbour's conormal at the shared edge is this triangle's, reversed.
  const auto& row = reference[oo].slope[static_cast<size_t>(facing)];
  for (size_t a = 0; a < 6; ++a) pl.coef(k, slot[a]) -= weight * row[static_cast<Eigen::Index>(a)];
  return true;
}

// Each edge's agreed gradient along its conormal, w_k = sum_a coef(k, a) x_a, and the map from
// the slopes to II with the free edges' slopes eliminated: on a free edge the slope minimizing
// s^T C^T Q C s, so the moment across it, n^T (dE/dII) n, vanishes. A shared edge takes the mean
// of the fits that count on its two sides (weighted by their conditioning: any weights summing to
// one keep the patch test), or where neither counts the mean of the two planes (consistent on
// regular meshes only, and rare: beside the rim and other materials). The own plane's part adds
// nothing to the slope (t is normal to it), so only the neighbour's half is written. A clamped
// edge takes the stiff neighbour's plane.
ShellTriangles::Plan ShellTriangles::plan(int i) const {
  const auto k0 = static_cast<size_t>(i);
  const ShellReference& ref = reference[k0];
  Plan out;
  out.edges = edges(i);
  const std::array<const PlateLayer*, 2> layers{&latex[k0], &resin[k0]};
  static const std::array<Eigen::Matrix2d, 3> unit{(Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 1, 1, 0).finished(),
                                                   (Eigen::Matrix2d() << 0, 0, 0, 1).finished()};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out.form(r, c) =
          plate_form(layers, unit[static_cast<size_t>(r)], unit[static_cast<size_t>(c)]);
  const bool own = counts(ref, out.edges);
  for (int k = 0; k < 3; ++k) {
    const auto kk = static_cast<size_t>(k);
    if (out.edges[kk] == Edge::free) continue;
    const int o = neighbour[k0][kk];
    const auto oo = static_cast<size_t>(o);
    const Vec2& n = ref.conormal[kk];
    // The plane's slope of neighbour o along this conormal, times `weight`, on its corners.
    auto add_plane = [&](double weight) {
      const Eigen::RowVector3d row = n.transpose() * reference[oo].gradient;
      for (size_t c = 0; c < 3; ++c)  // the neighbour's corners: this edge's and slot 3 + k
        if (const int a = slot_of(i, v[oo][c]); a >= 0)
          out.coef(k, a) += weight * row[static_cast<Eigen::Index>(c)];
    };
    if (out.edges[kk] == Edge::clamped) {
      add_plane(1.0);
      continue;
    }
    const double wi = own ? ref.quality : 0.0;
    const double wo = fit_counts(o) ? reference[oo].quality : 0.0;
    if (wi + wo == 0.0) {
      add_plane(0.5);
      continue;
    }
    const Eigen::Matrix<double, 3, 12> before = out.coef;
    if (wi > 0.0) out.coef.row(k).head<6>() += wi / (wi + wo) * ref.slope[kk];
    if (wo > 0.0 && !add_neighbour_slope(i, k, o, wo / (wi + wo), out)) {
      out.coef = before;  // that fit's points are not all in the stencil: the planes' mean
      add_plane(0.5);
    }
  }
  // Free slopes s_f = -(B_ff)^-1 B_fk s_k, B = C^T Q C, in fixed 3 x 3 blocks (built once per
  // change of the rest state, planned()): with the masks P_f and P_k, (P_f B P_f + P_k) is B_ff
  // padded with the identity. With a rest curvature r the free slopes minimize
  // (C s - r)^T Q (C s - r) and gain (B_ff)^-1 P_f C^T Q r.
  const Eigen::Vector3d rest = coat_share * coat_curvature[k0];
  Eigen::Matrix3d keep = Eigen::Matrix3d::Identity();
  out.shift = -rest;
  if (out.edges[0] == Edge::free || out.edges[1] == Edge::free || out.edges[2] == Edge::free) {
    Eigen::Matrix3d pf = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 3; ++k) pf(k, k) = out.edges[static_cast<size_t>(k)] == Edge::free;
    const Eigen::Matrix3d pk = Eigen::Matrix3d::Identity() - pf;
    const Eigen::Matrix3d b = ref.curvature.transpose() * out.form * ref.curvature;
    const Eigen::Matrix3d padded = pf * b * pf + pk;
    const auto solver = padded.completeOrthogonalDecomposition();
    keep = pk - solver.solve(Eigen::Matrix3d(pf * b * pk));
    if (!rest.isZero(0.0))
      out.shift += ref.curvature *
                   solver.solve(Eigen::Vector3d(pf * ref.curvature.transpose() * out.form * rest));
  }
  out.map = ref.curvature * keep;
  return out;
}

namespace {

PlateLayer plate_at(const Eigen::Matrix2d& metric, double d, double nu) {
  const double det = metric.determinant();
  if (!(det > 0.0)) throw std::invalid_argument("shell triangle: degenerate rest shape");
  return {metric.inverse(), 0.5 * std::sqrt(det), d, nu};
}

// A stencil of corners c with every other slot holding its corner as a placeholder (slot 3 + k
// and, until link_neighbours, 6 + 2k and 7 + 2k hold corner k).
std::array<int, 12> corner_stencil(const std::array<int, 3>& c) {
  std::array<int, 12> ids{};
  for (size_t a = 0; a < 12; ++a) ids[a] = c[a < 3 ? a : (a < 6 ? a - 3 : (a - 6) / 2)];
  return ids;
}

Eigen::Matrix2d metric_of(const Points& x, const std::array<int, 12>& p) {
  return triangle_metric(x.col(p[0]), x.col(p[1]), x.col(p[2]));
}

// The triangle's two edges from its first corner, in the plane of the frame (m).
Eigen::Matrix2d in_plane_edges(const Points& x, const std::array<int, 12>& p) {
  Eigen::Matrix2d e;
  e << (x.col(p[1]) - x.col(p[0])).head<2>(), (x.col(p[2]) - x.col(p[0])).head<2>();
  return e;
}

}  // namespace

void ShellTriangles::add_mesh(const std::vector<std::array<int, 3>>& triangles,
                              const Points& reference_x, double d, double nu) {
  if (!(d >= 0.0) || !(nu >= 0.0 && nu < 1.0))
    throw std::invalid_argument("shell triangles: a negative stiffness or nu outside [0, 1)");
  // Each directed edge (a, b) with its triangle; the neighbour across it holds (b, a).
  std::map<std::pair<int, int>, int> owner;
  const int first = size();
  for (size_t t = 0; t < triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k)
      if (!owner
               .try_emplace({triangles[t][k], triangles[t][(k + 1) % 3]},
                            first + static_cast<int>(t))
               .second)
        throw std::invalid_argument(
            "shell triangles: an edge met twice in one direction (a non-manifold mesh or "
            "triangles of opposite orientation)");
  for (const auto& t : triangles) {
    std::array<int, 12> ids = corner_stencil(t);
    std::array<int, 3> across{-1, -1, -1};
    std::array<bool, 3> has{};
    std::array<Vec2, 3> corner, far;
    for (size_t k = 0; k < 3; ++k) {
      corner[k] = reference_x.col(t[k]).head<2>();
      const auto o = owner.find({t[(k + 2) % 3], t[(k + 1) % 3]});
      if (o == owner.end()) continue;
      across[k] = o->second;
      const auto& u = triangles[static_cast<size_t>(o->second - first)];
      for (int c : u)
        if (c != t[(k + 1) % 3] && c != t[(k + 2) % 3]) ids[3 + k] = c;
      has[k] = true;
    }
    // A neighbour sharing its far corner with another leaves five distinct points: not posed.
    for (size_t k = 0; k < 3; ++k) far[k] = reference_x.col(ids[3 + k]).head<2>();
    if (ids[3] == ids[4] || ids[4] == ids[5] || ids[3] == ids[5]) has = {};
    reference.push_back(reference_of(corner, far, has));
    const Eigen::Matrix2d g = metric_of(reference_x, ids);
    latex.push_back(plate_at(g, d, nu));
    resin.emplace_back();
    v.push_back(ids);
    neighbour.push_back(across);
    natural_metric.push_back(g);
    frame_metric.push_back(g);
    coat_curvature.push_back(Eigen::Vector3d::Zero());
  }
  link_neighbours();
}

void ShellTriangles::link_neighbours() {
  invalidate();  // every change of the mesh ends here
  for (size_t t = 0; t < v.size(); ++t)
    for (size_t k = 0; k < 3; ++k) {
      const int o = neighbour[t][k];
      v[t][6 + 2 * k] = v[t][7 + 2 * k] = v[t][k];
      if (o < 0) continue;
      size_t slot = 6 + 2 * k;
      for (size_t j = 0; j < 3; ++j)
        if (neighbour[static_cast<size_t>(o)][j] != static_cast<int>(t))
          v[t][std::min(slot++, 7 + 2 * k)] = v[static_cast<size_t>(o)][3 + j];
    }
}

void ShellTriangles::split_corners(const std::vector<std::array<int, 3>>& corners) {
  for (size_t t = 0; t < v.size(); ++t)
    for (size_t k = 0; k < 3; ++k) v[t][k] = corners[t][k];
  const auto holds = [&](int o, int id) {
    const auto& c = v[static_cast<size_t>(o)];
    return c[0] == id || c[1] == id || c[2] == id;
  };
  for (size_t t = 0; t < v.size(); ++t)
    for (size_t k = 0; k < 3; ++k) {
      int& o = neighbour[t][k];
      const int a = v[t][(k + 1) % 3], b = v[t][(k + 2) % 3];
      if (o >= 0 && !(holds(o, a) && holds(o, b))) o = -1;
      v[t][3 + k] = v[t][k];  // the far corner, or the placeholder of a free edge
      if (o < 0) continue;
      for (size_t j = 0; j < 3; ++j) {
        const int c = v[static_cast<size_t>(o)][j];
        if (c != a && c != b) v[t][3 + k] = c;
      }
    }
  link_neighbours();
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
  keep_where(reference, keep);
  keep_where(latex, keep);
  keep_where(resin, keep);
  keep_where(natural_metric, keep);
  keep_where(frame_metric, keep);
  keep_where(coat_curvature, keep);
  link_neighbours();
}

double ShellTriangles::plate(int i) const {
  return latex[static_cast<size_t>(i)].d + resin[static_cast<size_t>(i)].d;
}

namespace {

// A triangle's state for its kernel: the unit normal t = c / |c| (c = d1 x d2, d1 = x1 - x0,
// d2 = x2 - x0), the agreed gradients w_k (columns), the slopes s_k = t . w_k, ii = II - II0 =
// map s + shift and the energy's derivative in the slopes.
struct ShellState {
  Vec3 d1, d2, t;
  double c_norm = 0.0;  // 0: a face collapsed to a line, which has no normal and reads nothing
  Eigen::Matrix3d w;
  Eigen::Vector3d s, ii, de_ds;
};

ShellState state_of(const ShellTriangles::Plan& pl, const std::array<int, 12>& p, const Points& x) {
  ShellState st;
  st.d1 = x.col(p[1]) - x.col(p[0]);
  st.d2 = x.col(p[2]) - x.col(p[0]);
  const Vec3 c = st.d1.cross(st.d2);
  st.c_norm = c.norm();
  st.w.setZero();
  for (size_t a = 0; a < 12; ++a)
    st.w += x.col(p[a]) * pl.coef.col(static_cast<Eigen::Index>(a)).transpose();
  st.t = st.c_norm > 0.0 ? Vec3(c / st.c_norm) : Vec3::Zero();
  st.s = st.w.transpose() * st.t;
  st.ii = pl.map * st.s + pl.shift;
  st.de_ds = 2.0 * pl.map.transpose() * (pl.form * st.ii);
  return st;
}

// The energy's gradient over d1, d2, w0, w1, w2: dE/dw_k = dE/ds_k t, and through the normal
// dE/dc = P y / |c| (P = I - t t^T, y = sum_k dE/ds_k w_k), dc = dd1 x d2 + d1 x dd2.
Eigen::Matrix<double, 15, 1> reduced_gradient(const ShellState& st) {
  Eigen::Matrix<double, 15, 1> g = Eigen::Matrix<double, 15, 1>::Zero();
  if (st.c_norm == 0.0) return g;
  const Vec3 y = st.w * st.de_ds;
  const Vec3 dc = (y - st.t * st.t.dot(y)) / st.c_norm;
  g.segment<3>(0) = st.d2.cross(dc);
  g.segment<3>(3) = dc.cross(st.d1);
  for (int k = 0; k < 3; ++k) g.segment<3>(6 + 3 * k) = st.de_ds[k] * st.t;
  return g;
}

Eigen::Matrix3d cross_matrix(const Vec3& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

// The same energy's Hessian over those 15 variables, in closed form. With A = d2E/ds2 and the
// slopes' gradients J (rows), H = J^T A J + sum_k dE/ds_k d2s_k, where s_k = w_k . c / |c| and
// c = d1 x d2 is bilinear: d2s_k holds t's second derivative in c (through d1, d2), the normal's
// derivative P / |c| between w_k and c, and q_k = P w_k / |c| against c's own second derivative.
Eigen::Matrix<double, 15, 15> reduced_hessian(const ShellTriangles::Plan& pl,
                                              const ShellState& st) {
  using Mat15 = Eigen::Matrix<double, 15, 15>;
  if (st.c_norm == 0.0) return Mat15::Zero();
  const double n = st.c_norm;
  const Vec3& t = st.t;
  const Eigen::Matrix3d proj = Eigen::Matrix3d::Identity() - t * t.transpose();
  Eigen::Matrix<double, 3, 6> dc;  // dc/d(d1, d2)
  dc << -cross_matrix(st.d2), cross_matrix(st.d1);
  Eigen::Matrix<double, 3, 15> jac = Eigen::Matrix<double, 3, 15>::Zero();
  for (int k = 0; k < 3; ++k) {
    const Vec3 q = proj * st.w.col(k) / n;
    jac.block<1, 6>(k, 0) = q.transpose() * dc;
    jac.block<1, 3>(k, 6 + 3 * k) = t.transpose();
  }
  const Eigen::Matrix3d a = 2.0 * pl.map.transpose() * pl.form * pl.map;
  // Small fixed-size products, coefficient by coefficient (Eigen's GEMM costs more at this size).
  const Eigen::Matrix<double, 15, 3> ja = jac.transpose().lazyProduct(a);
  Mat15 h = ja.lazyProduct(jac);
  // sum_k G_k (w_k . d2t/dc2), y = sum_k G_k w_k: t_i's second derivative contracted with y.
  const Vec3 y = st.w * st.de_ds;
  const double yt = y.dot(t);
  const Eigen::Matrix3d tyy = (3.0 * yt * t * t.transpose() - y * t.transpose() -
                               t * y.transpose() - yt * Eigen::Matrix3d::Identity()) /
                              (n * n);
  h.block<6, 6>(0, 0) += dc.transpose() * tyy * dc;
  // c's own second derivative against dE/dc = P y / |c|: (dd1 x dd2) . g_c.
  const Eigen::Matrix3d gc = cross_matrix(proj * y / n);
  h.block<3, 3>(0, 3) -= gc;
  h.block<3, 3>(3, 0) += gc;
  // Between w_k and c: G_k P / |c|.
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix<double, 3, 6> m = st.de_ds[k] / n * proj * dc;
    h.block<3, 6>(6 + 3 * k, 0) += m;
    h.block<6, 3>(0, 6 + 3 * k) += m.transpose();
  }
  return h;
}

// L^T h L for the map L from the stencil's 36 coordinates to the 15 variables, L = S (x) I3 with
// S's rows d1 = x1 - x0, d2 = x2 - x0 and w_k = coef(k, .): coordinate by coordinate,
// (S^T h_ab S) for each pair of axes a, b (h_ab the 5 x 5 block of those axes).
Eigen::Matrix<double, 36, 36> stencil_hessian(const ShellTriangles::Plan& pl,
                                              const Eigen::Matrix<double, 15, 15>& h) {
  Eigen::Matrix<double, 5, 12> sel = Eigen::Matrix<double, 5, 12>::Zero();
  sel(0, 0) = sel(1, 0) = -1.0;
  sel(0, 1) = sel(1, 2) = 1.0;
  sel.bottomRows<3>() = pl.coef;
  Eigen::Matrix<double, 36, 36> out;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const Eigen::Matrix<double, 5, 5> hab =
          Eigen::Map<const Eigen::Matrix<double, 5, 5>, 0, Eigen::Stride<45, 3>>(h.data() + a +
                                                                                 15 * b);
      const Eigen::Matrix<double, 12, 5> sh = sel.transpose().lazyProduct(hab);
      const Eigen::Matrix<double, 12, 12> r = sh.lazyProduct(sel);
      for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 12; ++i) out(3 * i + a, 3 * j + b) = r(i, j);
    }
  return out;
}

}  // namespace

const ShellTriangles::Plan& ShellTriangles::planned(int i) const {
  const std::vector<Plan>& all = plans_.get([this] {
    std::vector<Plan> out(static_cast<size_t>(size()));
    for (int k = 0; k < size(); ++k) out[static_cast<size_t>(k)] = plan(k);
    return out;
  });
  return all[static_cast<size_t>(i)];
}

double ShellTriangles::energy(int i, const Points& x) const {
  const Plan& pl = planned(i);
  const ShellState st = state_of(pl, v[static_cast<size_t>(i)], x);
  return st.ii.dot(pl.form * st.ii);
}

void ShellTriangles::add_forces(const Points& x, const Points*, int begin, int end,
                                Points& f) const {
  for (int i = begin; i < end; ++i) {
    if (!active(i)) continue;
    const Plan& pl = planned(i);
    const auto& p = v[static_cast<size_t>(i)];
    const ShellState st = state_of(pl, p, x);
    const Eigen::Matrix<double, 15, 1> g = reduced_gradient(st);
    f.col(p[0]) += g.segment<3>(0) + g.segment<3>(3);
    f.col(p[1]) -= g.segment<3>(0);
    f.col(p[2]) -= g.segment<3>(3);
    // dE/dx_a through the agreed gradients: (sum_k coef(k, a) dE/ds_k) t.
    const Eigen::Matrix<double, 12, 1> along = pl.coef.transpose() * st.de_ds;
    for (size_t a = 0; a < 12; ++a) f.col(p[a]) -= along[static_cast<Eigen::Index>(a)] * st.t;
  }
}

Eigen::Matrix<double, 36, 36> ShellTriangles::hessian(int i, const Points& x, bool project) const {
  const Plan& pl = planned(i);
  const ShellState st = state_of(pl, v[static_cast<size_t>(i)], x);
  Eigen::Matrix<double, 15, 15> h = reduced_hessian(pl, st);
  h = 0.5 * (h + h.transpose());
  if (project) h = project_psd(h);
  return stencil_hessian(pl, h);
}

void ShellTriangles::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    if (!active(i)) continue;
    const Eigen::Matrix<double, 36, 36> h = hessian(i, x, true);
    const auto& p = v[static_cast<size_t>(i)];
    for (int c = 0; c < 12; ++c)
      diag[p[static_cast<size_t>(c)]] += h.block<3, 3>(3 * c, 3 * c).trace() / 3.0;
  }
}

void ShellTriangles::update(const ReleaseLevel& release) {
  invalidate();
  coat_share = release.releasing ? 1.0 - release.level : 0.0;
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
  invalidate();
  const double d = bending_stiffness(at.resin);
  const double per_strain =
      at.bilayer ? bilayer_curvature_per_strain(at.sheet.material, at.resin) : 0.0;
  const double sign = at.side >= 0 ? 1.0 : -1.0;
  int count = 0;
  for (int i = 0; i < size(); ++i) {
    const auto k = static_cast<size_t>(i);
    const auto& p = v[k];
    if (!pattern_covers(at, p[0], p[1], p[2]))
      continue;  // a later coat replaces, as the membrane's
    resin[k] = plate_at(metric_of(at.x, p), d, 1.0 / 3.0);
    coat_curvature[k].setZero();  // resin through the thickness curls nothing
    if (at.bilayer) {
      // The coat on the convex side: a bulge towards it, II < 0 seen from that face.
      const Eigen::Matrix2d e = in_plane_edges(at.x, p);
      const Eigen::Matrix2d f = in_plane_gradient(at.sheet.model.reference, at.x, p[0], p[1], p[2]);
      const Eigen::Matrix2d k0 = -sign * per_strain * misfit_strain(f);
      const Eigen::Matrix2d ii = e.transpose() * k0 * e;
      coat_curvature[k] = Eigen::Vector3d(ii(0, 0), ii(0, 1), ii(1, 1));
    }
    ++count;
  }
  return count;
}

void ShellTriangles::grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
                          const ReleaseLevel& release) {
  invalidate();
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
    std::array<int, 12> ids = corner_stencil(mapped);
    for (size_t c = 0; c < 3; ++c) {
      const int far = r.new_of_old[static_cast<size_t>(old.v[k][3 + c])];
      if (old.neighbour[k][c] >= 0 && far >= 0) ids[3 + c] = far;
    }
    v.push_back(ids);
    neighbour.push_back(old.neighbour[k]);
    reference.push_back(old.reference[k]);
    latex.push_back(old.latex[k]);
    resin.push_back(old.resin[k]);
    natural_metric.push_back(old.natural_metric[k]);
    frame_metric.push_back(old.frame_metric[k]);
    coat_curvature.push_back(old.coat_curvature[k]);
  }
  coat_share = old.coat_share;
  for (size_t t = static_cast<size_t>(first); t < v.size(); ++t)
    for (size_t c = 0; c < 3; ++c) {
      int& o = neighbour[t][c];
      if (o >= 0) o = renumber[static_cast<size_t>(o)];
      if (o < 0) v[t][3 + c] = v[t][c];
    }
  link_neighbours();
}

}  // namespace membra
