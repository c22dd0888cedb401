#include "membra/model/elements/bending.hpp"

#include <map>

#include "membra/model/elements/bend_kernel.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<Bending>);

void Bending::add(int a, int b, int c, double stiffness_, double factor_) {
  v.push_back({a, b, c});
  stiffness.push_back(stiffness_);
  factor.push_back(factor_);
  latex_stiffness.push_back(stiffness_);
  resin_stiffness.push_back(0.0);
  resin_fraction.push_back(0.0);
}

void Bending::filter(const std::vector<bool>& keep) {
  keep_where(v, keep);
  for (auto* a : {&stiffness, &factor, &latex_stiffness, &resin_stiffness, &resin_fraction})
    keep_where(*a, keep);
}

void Bending::reset_material() {
  latex_stiffness = stiffness;
  resin_stiffness.assign(stiffness.size(), 0.0);
  resin_fraction.assign(stiffness.size(), 0.0);
}

double Bending::energy(int i, const Points& x) const {
  const auto& e = v[static_cast<size_t>(i)];
  return bend_eval(x.col(e[0]), x.col(e[1]), x.col(e[2]), stiffness[i]).energy;
}

void Bending::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const auto& e = v[static_cast<size_t>(i)];
    const BendEval r = bend_eval(x.col(e[0]), x.col(e[1]), x.col(e[2]), stiffness[i]);
    for (int k = 0; k < 3; ++k) f.col(e[k]) -= r.grad[k];
  }
}

Eigen::Matrix<double, 9, 9> Bending::hessian(int i, const Points& x, bool project) const {
  const auto& e = v[static_cast<size_t>(i)];
  return bend_hessian(x.col(e[0]), x.col(e[1]), x.col(e[2]), stiffness[i], project);
}

void Bending::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    // Small-angle energy c |x0 - 2 x1 + x2|^2 / L^2: Hessian row sums 8c/L^2 (ends), 16c/L^2
    // (node).
    const auto& e = v[static_cast<size_t>(i)];
    const double l2 = 0.25 * (x.col(e[2]) - x.col(e[0])).squaredNorm();
    if (l2 <= 0.0) continue;
    const double k = 8.0 * stiffness[i] / l2;
    diag[e[0]] += k;
    diag[e[1]] += 2.0 * k;
    diag[e[2]] += k;
  }
}

double Bending::composite(double latex, double resin, double fraction) {
  return 1.0 / ((1.0 - fraction) / latex + fraction / (latex + resin));
}

void Bending::set_fraction(int e, double fraction) {
  resin_fraction[e] = fraction;
  stiffness[e] = composite(latex_stiffness[e], resin_stiffness[e], fraction);
}

double Bending::rate(int e) const {
  const double c = stiffness[e], cl = latex_stiffness[e];
  return c * c * (1.0 / cl - 1.0 / (cl + resin_stiffness[e]));
}

ResinFootprint Bending::footprint(int e, const Points& x) const {
  const auto& p = v[static_cast<size_t>(e)];
  ResinFootprint f;
  f.count = 2;
  f.segment[0] = {x.col(p[0]).head<2>(), x.col(p[1]).head<2>(), 0.5};
  f.segment[1] = {x.col(p[1]).head<2>(), x.col(p[2]).head<2>(), 0.5};
  f.site = x.col(p[1]).head<2>();
  return f;
}

double Bending::resin_rate(int e, const Points& x, const Points& w, const ReleaseLevel&) const {
  const auto& p = v[static_cast<size_t>(e)];
  const BendEval unit = bend_eval(x.col(p[0]), x.col(p[1]), x.col(p[2]), 1.0);
  double work = 0.0;
  for (int i = 0; i < 3; ++i) work += unit.grad[i].dot(w.col(p[i]));
  return rate(e) * work;
}

int Bending::impregnate(const Impregnation& at) {
  const Points& x = at.x;
  const double d_resin = bending_stiffness(at.resin);
  const GridSheet& g = at.sheet.grid;
  const Points& reference = at.sheet.model.reference;
  const double hx_now = g.hx() * at.stretch.x(), hy_now = g.hy() * at.stretch.y();
  int count = 0;
  for (int e = 0; e < size(); ++e) {
    const auto& p = v[static_cast<size_t>(e)];
    const auto share = [&](const Pattern& pattern) {
      return 0.5 * (fraction_inside(pattern, x.col(p[0]).head<2>(), x.col(p[1]).head<2>(), 8) +
                    fraction_inside(pattern, x.col(p[1]).head<2>(), x.col(p[2]).head<2>(), 8));
    };
    if (share(at.pattern) <= 0.0) continue;
    ++count;
    // Never less than before: resin cured in an earlier state stays.
    const double fraction = std::max(resin_fraction[e], share(at.all));
    // The resin plate forms in the stretched sheet, whose cells are hx' x hy': its elements
    // take the plate weights of those cells.
    const Vec3 span = reference.col(p[2]) - reference.col(p[0]);
    const auto [ni, nj] = g.node(p[1]);
    const int di = span.x() > 0 ? 1 : span.x() < 0 ? -1 : 0;
    const int dj = span.y() > 0 ? 1 : span.y() < 0 ? -1 : 0;
    resin_stiffness[e] = d_resin * bending_factor(g, ni, nj, di, dj, hx_now, hy_now);
    set_fraction(e, fraction);
  }
  return count;
}

void Bending::carry(const Bending& old, const Rebuild& r) {
  const GridSheet& g = r.old_sheet.grid;
  const GridSheet& ng = r.new_sheet.grid;
  auto node_id = [](const GridSheet& grid, int p) {
    const auto [i, j] = grid.node(p);
    return j * grid.nx() + i;
  };
  std::map<std::array<int, 3>, int> old_element;
  for (int e = 0; e < old.size(); ++e) {
    const auto& p = old.v[static_cast<size_t>(e)];
    old_element[{node_id(g, p[0]), node_id(g, p[1]), node_id(g, p[2])}] = e;
  }
  std::vector<bool> keep(static_cast<size_t>(size()), false);
  for (int e = 0; e < size(); ++e) {
    const auto& p = v[static_cast<size_t>(e)];
    const auto it = old_element.find({node_id(ng, p[0]), node_id(ng, p[1]), node_id(ng, p[2])});
    if (it == old_element.end()) continue;
    const int o = it->second;
    keep[static_cast<size_t>(e)] = true;
    resin_stiffness[e] = old.resin_stiffness[o] * factor[e] / old.factor[o];
    // Bare latex keeps its stiffness exactly (the rule's 1 / (1 / c) may round).
    resin_fraction[e] = old.resin_fraction[o];
    stiffness[e] = resin_fraction[e] > 0.0
                       ? composite(latex_stiffness[e], resin_stiffness[e], resin_fraction[e])
                       : latex_stiffness[e];
  }
  filter(keep);
}

}  // namespace membra
