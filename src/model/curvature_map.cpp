#include "membra/model/curvature_map.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

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

// Newton's method for F(u) = L u + s K e^{2u} = 0 on the interior unknowns, from u. Returns true
// when it converged (u updated), false otherwise (u untouched).
bool newton(const GridSheet& g, const std::vector<bool>& edge, const std::vector<int>& unknown,
            const std::vector<double>& K, double s, const ConformalOptions& o,
            std::vector<double>& u) {
  const int n = static_cast<int>(std::count(edge.begin(), edge.end(), false));
  const double ihx2 = 1.0 / (g.hx() * g.hx()), ihy2 = 1.0 / (g.hy() * g.hy());
  const double scale = g.hx() * g.hy();  // residuals in units of K h^2
  std::vector<double> v = u;
  for (int it = 0; it < o.max_newton; ++it) {
    Eigen::VectorXd f(n);
    std::vector<Eigen::Triplet<double>> jac;
    double worst = 0.0;
    for (int p = 0; p < g.num_particles(); ++p) {
      const int r = unknown[p];
      if (r < 0) continue;
      const auto [i, j] = g.node(p);
      const double e2u = std::exp(2.0 * v[p]);
      double lap = -2.0 * (ihx2 + ihy2) * v[p];
      const int nb[4] = {g.particle(i - 1, j), g.particle(i + 1, j), g.particle(i, j - 1),
                         g.particle(i, j + 1)};
      for (int k = 0; k < 4; ++k) {
        const double w = k < 2 ? ihx2 : ihy2;
        lap += w * v[nb[k]];  // edge neighbours hold u = 0 (v stays 0 there)
        if (unknown[nb[k]] >= 0) jac.emplace_back(r, unknown[nb[k]], w);
      }
      f[r] = lap + s * K[p] * e2u;
      jac.emplace_back(r, r, -2.0 * (ihx2 + ihy2) + 2.0 * s * K[p] * e2u);
      worst = std::max(worst, std::abs(f[r]) * scale);
    }
    if (!std::isfinite(worst)) return false;
    if (worst <= o.tolerance) {
      u = v;
      return true;
    }
    Eigen::SparseMatrix<double> J(n, n);
    J.setFromTriplets(jac.begin(), jac.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(J);
    if (lu.info() != Eigen::Success) return false;
    const Eigen::VectorXd du = lu.solve(-f);
    if (lu.info() != Eigen::Success || !du.allFinite()) return false;
    for (int p = 0; p < g.num_particles(); ++p)
      if (unknown[p] >= 0) v[p] += du[unknown[p]];
  }
  return false;
}

}  // namespace

ConformalFactor conformal_factor(const Sheet& sheet, const std::vector<double>& K,
                                 const ConformalOptions& o) {
  const GridSheet& g = sheet.grid;
  const std::vector<bool> edge = edge_particles(g);
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
    if (newton(g, edge, unknown, K, next, o, out.u)) {
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
  const std::vector<bool> edge = edge_particles(sheet.grid);
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
