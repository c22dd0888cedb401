#include "membra/model/elements/springs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "membra/model/elements/spring_kernel.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<Springs>);

std::string_view to_string(SpringFamily f) {
  switch (f) {
    case SpringFamily::stretch:
      return "stretch";
    case SpringFamily::shear:
      return "shear";
    case SpringFamily::flex:
      return "flex";
    case SpringFamily::added:
      return "added";
  }
  return "unknown";
}

int Springs::add(int pa, int pb, double l0, double k, double c, SpringFamily f, double w) {
  if (f == SpringFamily::added)
    throw std::invalid_argument("springs: added springs are a set of their own (AddedSprings)");
  a.push_back(pa);
  b.push_back(pb);
  rest_length.push_back(l0);
  stiffness.push_back(k);
  damping.push_back(c);
  family.push_back(f);
  width.push_back(w);
  natural_length.push_back(l0);
  latex_stiffness.push_back(k);
  resin_fraction.push_back(0.0);
  resin_stiffness.push_back(0.0);
  resin_length.push_back(l0);
  frame_length.push_back(l0);
  return size() - 1;
}

void Springs::filter(const std::vector<bool>& keep) {
  keep_where(a, keep);
  keep_where(b, keep);
  for (auto* v : {&rest_length, &stiffness, &damping, &width, &natural_length, &latex_stiffness,
                  &resin_fraction, &resin_stiffness, &resin_length, &frame_length})
    keep_where(*v, keep);
  keep_where(family, keep);
}

void Springs::reset_material() {
  natural_length = rest_length;
  latex_stiffness = stiffness;
  resin_fraction.assign(rest_length.size(), 0.0);
  resin_stiffness.assign(rest_length.size(), 0.0);
  resin_length = rest_length;
  frame_length = rest_length;
}

double Springs::energy(int i, const Points& x) const {
  return spring_energy(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i]);
}

void Springs::add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const {
  add_spring_forces(a, b, rest_length, stiffness, damping, x, v, begin, end, f);
}

Eigen::Matrix<double, 6, 6> Springs::hessian(int i, const Points& x, bool project) const {
  return spring_hessian(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i], project);
}

void Springs::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    const double k =
        spring_stiffness_estimate(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i]);
    diag[a[i]] += k;
    diag[b[i]] += k;
  }
}

ElementStress Springs::stress(int i, const Points& x, double thickness) const {
  return axial_stress(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i], width[i], thickness);
}

void Springs::begin_release(const Points& x) {
  for (int s = 0; s < size(); ++s) frame_length[s] = (x.col(b[s]) - x.col(a[s])).norm();
}

double Springs::latex_rest(int s, const ReleaseLevel& release) const {
  const double l_nat = natural_length[s];
  return release.releasing ? l_nat + release.level * (frame_length[s] - l_nat) : l_nat;
}

void Springs::update(int s, const ReleaseLevel& release) {
  const double rest = latex_rest(s, release);
  const double f = resin_fraction[s], kl = latex_stiffness[s];
  if (f <= 0.0) {
    rest_length[s] = rest;
    stiffness[s] = kl;
    return;
  }
  const double k_in = resin_stiffness[s] + kl;
  const double rest_in = (resin_stiffness[s] * resin_length[s] + kl * rest) / k_in;
  stiffness[s] = 1.0 / ((1.0 - f) / kl + f / k_in);
  rest_length[s] = (1.0 - f) * rest + f * rest_in;
}

void Springs::update(const ReleaseLevel& release) {
  for (int s = 0; s < size(); ++s) update(s, release);
}

SpringRate Springs::rate(int s, const ReleaseLevel& release) const {
  const double kl = latex_stiffness[s], kr = resin_stiffness[s];
  const double rest = latex_rest(s, release);
  const double k_in = kr + kl;
  const double rest_in = (kr * resin_length[s] + kl * rest) / k_in;
  const double k = stiffness[s];
  return {k * k * (1.0 / kl - 1.0 / k_in), rest_in - rest};
}

ResinFootprint Springs::footprint(int s, const Points& x) const {
  ResinFootprint f;
  f.count = 1;
  f.segment[0] = {x.col(a[s]).head<2>(), x.col(b[s]).head<2>(), 1.0};
  f.site = 0.5 * (x.col(a[s]) + x.col(b[s])).head<2>();
  return f;
}

void Springs::set_resin_fraction(int s, double f, const ReleaseLevel& release) {
  resin_fraction[s] = f;
  update(s, release);
}

double Springs::resin_rate(int s, const Points& x, const Points& w,
                           const ReleaseLevel& release) const {
  const Vec3 d = x.col(b[s]) - x.col(a[s]);
  const double l = d.norm();
  if (l <= 0.0) return 0.0;
  // grad E . w = k (l - l0) dl, dl = n . (w_b - w_a); its derivative in f.
  const double dl = d.dot(w.col(b[s]) - w.col(a[s])) / l;
  const SpringRate r = rate(s, release);
  return (r.dk * (l - rest_length[s]) - stiffness[s] * r.dl0) * dl;
}

std::vector<LocalGrowth> Springs::growth(const GrowthField& field, const Points& paper) const {
  std::vector<LocalGrowth> g(static_cast<size_t>(size()));
  for (int s = 0; s < size(); ++s)
    g[static_cast<size_t>(s)] = segment_growth(field, paper, a[s], b[s], to_string(family[s]));
  return g;
}

void Springs::grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
                   const ReleaseLevel& release) {
  for (int s = 0; s < size(); ++s) {
    const double ratio = segment_ratio(g[static_cast<size_t>(s)], paper, a[s], b[s]);
    if (ratio == 1.0) continue;
    const double k = std::pow(ratio, exponent);
    natural_length[s] *= k;
    frame_length[s] *= k;
    update(s, release);
  }
}

int Springs::impregnate(const Impregnation& at) {
  const LatticeStiffness& kl = at.sheet.stiffness;
  const LatticeStiffness kr = homogenize(at.resin, kl.flex > 0.0 ? kl.flex / kl.stretch : 0.0);
  const Points& x = at.x;
  int count = 0;
  for (int s = 0; s < size(); ++s) {
    const Vec2 pa = x.col(a[s]).head<2>(), pb = x.col(b[s]).head<2>();
    if (fraction_inside(at.pattern, pa, pb) <= 0.0) continue;
    ++count;
    // Never less than before: resin cured in an earlier state stays.
    resin_fraction[s] = std::max(resin_fraction[s], fraction_inside(at.all, pa, pb));
    resin_length[s] = (x.col(b[s]) - x.col(a[s])).norm();
    // Same family and the same share of a cell as the latex spring (half on the boundary).
    const bool shear = family[s] == SpringFamily::shear;
    const bool flex = family[s] == SpringFamily::flex;
    const double share = latex_stiffness[s] / (shear ? kl.shear : flex ? kl.flex : kl.stretch);
    resin_stiffness[s] = share * (shear ? kr.shear : flex ? kr.flex : kr.stretch);
    update(s, at.release);
  }
  return count;
}

void Springs::carry(const Springs& old, const Rebuild& r) {
  using Key = std::tuple<int, int, SpringFamily>;
  auto key = [](const GridSheet& g, const Springs& sp, int s) {
    const auto [ia, ja] = g.node(sp.a[s]);
    const auto [ib, jb] = g.node(sp.b[s]);
    const int na = ja * g.nx() + ia, nb = jb * g.nx() + ib;
    return Key{std::min(na, nb), std::max(na, nb), sp.family[s]};
  };
  std::map<Key, int> old_spring;
  for (int s = 0; s < old.size(); ++s) old_spring[key(r.old_sheet.grid, old, s)] = s;
  std::vector<bool> keep(static_cast<size_t>(size()), false);
  for (int s = 0; s < size(); ++s) {
    const auto it = old_spring.find(key(r.new_sheet.grid, *this, s));
    if (it == old_spring.end()) continue;
    const int o = it->second;
    keep[static_cast<size_t>(s)] = true;
    natural_length[s] = old.natural_length[o];
    frame_length[s] = old.frame_length[o];
    resin_fraction[s] = old.resin_fraction[o];
    resin_length[s] = old.resin_length[o];
    resin_stiffness[s] = old.resin_stiffness[o] * latex_stiffness[s] / old.latex_stiffness[o];
  }
  filter(keep);
}

}  // namespace membra
