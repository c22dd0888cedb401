#include "membra/model/curvature_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "membra/geometry/triangulation.hpp"

namespace membra {

std::vector<bool> edge_particles(const GridSheet& g) {
  std::vector<bool> edge(static_cast<size_t>(g.num_particles()), false);
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    edge[p] = g.particle(i - 1, j) < 0 || g.particle(i + 1, j) < 0 || g.particle(i, j - 1) < 0 ||
              g.particle(i, j + 1) < 0;
  }
  return edge;
}

namespace {

// The Liouville equation weakly, F(u) = A u + s M K e^{2u} = 0 on the interior particles: A the
// Laplacian's stiffness (its rows on the interior only) and M the area each particle stands for.
// On the grid, the 5-point stencil times the cell's area; on a mesh, the cotangent weights and
// a third of each triangle's area (the residual F is then in units of K times an area, as the
// grid's is of K h^2).
struct Liouville {
  Eigen::SparseMatrix<double> a;
  std::vector<double> mass;
};

Liouville grid_liouville(const GridSheet& g, const std::vector<bool>& edge) {
  const int n = g.num_particles();
  const double cell = g.hx() * g.hy(), wx = g.hy() / g.hx(), wy = g.hx() / g.hy();
  std::vector<Eigen::Triplet<double>> t;
  for (int p = 0; p < n; ++p) {
    if (edge[static_cast<size_t>(p)]) continue;  // every interior particle has its 4 neighbours
    const auto [i, j] = g.node(p);
    t.emplace_back(p, p, -2.0 * (wx + wy));
    t.emplace_back(p, g.particle(i - 1, j), wx);
    t.emplace_back(p, g.particle(i + 1, j), wx);
    t.emplace_back(p, g.particle(i, j - 1), wy);
    t.emplace_back(p, g.particle(i, j + 1), wy);
  }
  Liouville l;
  l.a.resize(n, n);
  l.a.setFromTriplets(t.begin(), t.end());
  l.mass.assign(static_cast<size_t>(n), cell);
  return l;
}

Liouville mesh_liouville(const Sheet& s) {
  const int n = s.model.num_particles();
  const Points& r = s.model.reference;
  std::vector<Eigen::Triplet<double>> t;
  Liouville l;
  l.mass.assign(static_cast<size_t>(n), 0.0);
  for (const Triangle& tri : s.triangles) {
    const std::array<int, 3> c{tri[0], tri[1], tri[2]};
    const double area = 0.5 * (r.col(c[1]) - r.col(c[0])).cross(r.col(c[2]) - r.col(c[0])).norm();
    for (size_t k = 0; k < 3; ++k) {
      l.mass[static_cast<size_t>(c[k])] += area / 3.0;
      // The edge opposite corner k weighs half the cotangent of the angle there.
      const int a = c[(k + 1) % 3], b = c[(k + 2) % 3];
      const Vec3 ea = r.col(a) - r.col(c[k]), eb = r.col(b) - r.col(c[k]);
      const double w = 0.5 * ea.dot(eb) / ea.cross(eb).norm();
      t.emplace_back(a, b, w);
      t.emplace_back(b, a, w);
      t.emplace_back(a, a, -w);
      t.emplace_back(b, b, -w);
    }
  }
  l.a.resize(n, n);
  l.a.setFromTriplets(t.begin(), t.end());
  return l;
}

// Newton's method for F(u) = 0 on the interior unknowns, from u. Returns true when it converged
// (u updated), false otherwise (u untouched).
bool newton(const Liouville& op, const std::vector<int>& unknown, int n,
            const std::vector<double>& K, double s, const ConformalOptions& o,
            std::vector<double>& u) {
  std::vector<double> v = u;
  const auto np = static_cast<Eigen::Index>(v.size());
  for (int it = 0; it < o.max_newton; ++it) {
    const Eigen::VectorXd au = op.a * Eigen::Map<const Eigen::VectorXd>(v.data(), np);
    Eigen::VectorXd f(n);
    std::vector<Eigen::Triplet<double>> jac;
    double worst = 0.0;
    for (Eigen::Index p = 0; p < np; ++p) {
      const int r = unknown[static_cast<size_t>(p)];
      if (r < 0) continue;
      const double sk = s * K[static_cast<size_t>(p)] * op.mass[static_cast<size_t>(p)] *
                        std::exp(2.0 * v[static_cast<size_t>(p)]);
      f[r] = au[p] + sk;
      jac.emplace_back(r, r, 2.0 * sk);
      worst = std::max(worst, std::abs(f[r]));
    }
    if (!std::isfinite(worst)) return false;
    if (worst <= o.tolerance) {
      u = v;
      return true;
    }
    for (Eigen::Index c = 0; c < op.a.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator e(op.a, c); e; ++e) {
        const int row = unknown[static_cast<size_t>(e.row())],
                  col = unknown[static_cast<size_t>(c)];
        if (row >= 0 && col >= 0) jac.emplace_back(row, col, e.value());
      }
    Eigen::SparseMatrix<double> J(n, n);
    J.setFromTriplets(jac.begin(), jac.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(J);
    if (lu.info() != Eigen::Success) return false;
    const Eigen::VectorXd du = lu.solve(-f);
    if (lu.info() != Eigen::Success || !du.allFinite()) return false;
    for (Eigen::Index p = 0; p < np; ++p)
      if (const int r = unknown[static_cast<size_t>(p)]; r >= 0) v[static_cast<size_t>(p)] += du[r];
  }
  return false;
}

}  // namespace

std::vector<bool> edge_particles(const Sheet& sheet) {
  if (!sheet.continuum()) return edge_particles(sheet.grid);
  // An edge of one triangle only is on the outline, a hole's rim or a slit's lip.
  return boundary_vertices(sheet.model.num_particles(), sheet.triangles);
}

ConformalFactor conformal_factor(const Sheet& sheet, const std::vector<double>& K,
                                 const ConformalOptions& o) {
  const std::vector<bool> edge = edge_particles(sheet);
  const Liouville op = sheet.continuum() ? mesh_liouville(sheet) : grid_liouville(sheet.grid, edge);
  std::vector<int> unknown(edge.size(), -1);
  int n = 0;
  for (size_t p = 0; p < edge.size(); ++p)
    if (!edge[p]) unknown[p] = n++;
  ConformalFactor out;
  out.u.assign(edge.size(), 0.0);
  if (n == 0) {
    out.reached = 1.0;
    return out;
  }
  double s = 0.0, step = 1.0 / o.continuation_steps;
  while (s < 1.0) {
    const double next = std::min(1.0, s + step);
    if (newton(op, unknown, n, K, next, o, out.u)) {
      s = next;
      step = std::min(step * 1.5, 1.0 / o.continuation_steps);
      continue;
    }
    step *= 0.5;
    if (step < 1e-3) break;
  }
  out.reached = s;
  if (s < 1.0) {
    std::ostringstream msg;
    msg << "the curvature map is not reachable with this sheet: lengths that carry it exist only "
           "up to "
        << std::round(s * 1000.0) / 10.0
        << " % of the map's values (the solution branch ends there; with constant K > 0 on a "
           "disk of radius R that happens at K R^2 = 1, a hemisphere). The form shown carries "
           "that share; scale K down, or give the sheet more room";
    out.message = msg.str();
  }
  return out;
}

LocalGrowth ConformalGrowth::at(std::span<const int> ids, std::span<const Vec2>,
                                std::string_view) const {
  double sum = 0.0;
  for (int p : ids) sum += u_[static_cast<size_t>(p)];
  LocalGrowth g;
  g.factor = std::exp(ids.size() == 2 ? 0.5 * sum : sum / static_cast<double>(ids.size()));
  return g;
}

CurvatureMatch match_curvature(const Sheet& sheet, const std::vector<double>& target,
                               const std::vector<double>& measured, double margin) {
  const std::vector<bool> edge = edge_particles(sheet);
  const Points& r = sheet.model.reference;
  std::vector<int> edge_list;
  for (size_t p = 0; p < edge.size(); ++p)
    if (edge[p]) edge_list.push_back(static_cast<int>(p));
  CurvatureMatch m;
  double st = 0, sm = 0, stt = 0, smm = 0, stm = 0, se = 0;
  for (int p = 0; p < sheet.model.num_particles(); ++p) {
    double d = std::numeric_limits<double>::infinity();
    for (int q : edge_list) d = std::min(d, (r.col(p) - r.col(q)).norm());
    if (d < margin) continue;
    ++m.interior;
    const double t = target[p], k = measured[p];
    st += t, sm += k, stt += t * t, smm += k * k, stm += t * k, se += (k - t) * (k - t);
  }
  if (m.interior == 0) return m;
  const double n = m.interior;
  m.mean_target = st / n;
  m.mean_measured = sm / n;
  m.rms_error = std::sqrt(se / n);
  const double rms_target = std::sqrt(stt / n);
  m.relative_rms_error = rms_target > 0.0 ? m.rms_error / rms_target : 0.0;
  const double vt = stt / n - m.mean_target * m.mean_target,
               vm = smm / n - m.mean_measured * m.mean_measured;
  const double cov = stm / n - m.mean_target * m.mean_measured;
  // Constant fields (a uniform target) have no correlation to speak of.
  if (vt > 1e-12 * stt / n && vm > 0.0) m.correlation = cov / std::sqrt(vt * vm);
  return m;
}

}  // namespace membra
