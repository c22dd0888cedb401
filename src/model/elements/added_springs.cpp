#include "membra/model/elements/added_springs.hpp"

#include <cmath>
#include <stdexcept>

#include "membra/model/elements/spring_kernel.hpp"

namespace membra {

static_assert(ElementSet<AddedSprings>);

void AddedSprings::push(int pa, int pb, double l0, double k, double c, double start) {
  a.push_back(pa);
  b.push_back(pb);
  rest_length.push_back(l0);
  stiffness.push_back(k);
  damping.push_back(c);
  start_length.push_back(start);
}

void AddedSprings::filter(const std::vector<bool>& keep) {
  keep_where(a, keep);
  keep_where(b, keep);
  for (auto* v : {&rest_length, &stiffness, &damping, &start_length}) keep_where(*v, keep);
}

namespace {

void check_added_springs_spec(const AddSpringsSpec& spec) {
  if (!spec.region) throw std::invalid_argument("add_springs: no region");
  if (spec.count < 1) throw std::invalid_argument("add_springs: count must be >= 1");
  if (!(spec.stiffness > 0.0)) throw std::invalid_argument("add_springs: stiffness must be > 0");
  if (!(spec.rest_factor > 0.0))
    throw std::invalid_argument("add_springs: rest factor must be > 0");
}

}  // namespace

int AddedSprings::add_along_edges(const std::vector<Triangle>& triangles, const Points& x,
                                  const AddSpringsSpec& spec) {
  check_added_springs_spec(spec);
  int pairs = 0;
  for (const auto& [edge, shared] : edge_counts(triangles)) {
    const auto [pa, pb] = edge;
    if (fraction_inside(*spec.region, x.col(pa).head<2>(), x.col(pb).head<2>()) < 0.5) continue;
    const double length = (x.col(pb) - x.col(pa)).norm();
    push(pa, pb, spec.rest_factor * length, spec.count * spec.stiffness, 0.0, length);
    ++pairs;
  }
  return pairs * spec.count;
}

int AddedSprings::add_beside(const Springs& lattice, const Points& x, const AddSpringsSpec& spec) {
  check_added_springs_spec(spec);
  int pairs = 0;
  for (int s = 0; s < lattice.size(); ++s) {
    if (spec.along && lattice.family[s] != *spec.along) continue;
    const int pa = lattice.a[s], pb = lattice.b[s];
    if (fraction_inside(*spec.region, x.col(pa).head<2>(), x.col(pb).head<2>()) < 0.5) continue;
    const double length = (x.col(pb) - x.col(pa)).norm();
    push(pa, pb, spec.rest_factor * length, spec.count * spec.stiffness, lattice.damping[s],
         length);
    ++pairs;
  }
  return pairs * spec.count;
}

void AddedSprings::set_level(int first, double rest_factor, double level) {
  for (int s = first; s < size(); ++s)
    rest_length[s] = start_length[s] * (1.0 + level * (rest_factor - 1.0));
}

double AddedSprings::energy(int i, const Points& x) const {
  return spring_energy(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i]);
}

void AddedSprings::add_forces(const Points& x, const Points* v, int begin, int end,
                              Points& f) const {
  add_spring_forces(a, b, rest_length, stiffness, damping, x, v, begin, end, f);
}

Eigen::Matrix<double, 6, 6> AddedSprings::hessian(int i, const Points& x, bool project) const {
  return spring_hessian(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i], project);
}

void AddedSprings::add_stiffness_estimate(const Points& x, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i) {
    const double k =
        spring_stiffness_estimate(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i]);
    diag[a[i]] += k;
    diag[b[i]] += k;
  }
}

ElementStress AddedSprings::stress(int i, const Points& x, double thickness) const {
  return axial_stress(x.col(a[i]), x.col(b[i]), rest_length[i], stiffness[i], 0.0, thickness);
}

std::vector<LocalGrowth> AddedSprings::growth(const GrowthField& field, const Points& paper) const {
  std::vector<LocalGrowth> g(static_cast<size_t>(size()));
  for (int s = 0; s < size(); ++s)
    g[static_cast<size_t>(s)] =
        segment_growth(field, paper, a[s], b[s], to_string(SpringFamily::added));
  return g;
}

void AddedSprings::grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
                        const ReleaseLevel&) {
  for (int s = 0; s < size(); ++s) {
    const double ratio = segment_ratio(g[static_cast<size_t>(s)], paper, a[s], b[s]);
    if (ratio != 1.0) rest_length[s] *= std::pow(ratio, exponent);
  }
}

void AddedSprings::carry(const AddedSprings& old, const Rebuild& r) {
  for (int s = 0; s < old.size(); ++s) {
    std::array<int, 2> p;
    if (!r.map(old.ids(s), p)) continue;
    push(p[0], p[1], old.rest_length[s], old.stiffness[s], old.damping[s], old.start_length[s]);
  }
}

}  // namespace membra
