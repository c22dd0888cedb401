#include "membra/design/resin_density.hpp"

#include <algorithm>

namespace membra {
namespace {

double fraction(const DensityField::Weights& w, const Eigen::VectorXd& rho) {
  double f = 0.0;
  for (int k = 0; k < 4; ++k) f += w.weight[k] * rho[w.cell[k]];
  return std::clamp(f, 0.0, 1.0);
}

void spread(const DensityField::Weights& w, double value, Eigen::VectorXd& out) {
  for (int k = 0; k < 4; ++k) out[w.cell[k]] += w.weight[k] * value;
}

}  // namespace

DensitySites density_sites(const Membrane& m, const Points& x_frame, const DensityField& field) {
  const Model& model = m.sheet.model;
  DensitySites s;
  s.cells = static_cast<int>(field.value.size());
  const Springs& sp = model.springs;
  s.spring.resize(static_cast<size_t>(sp.size()));
  for (int i = 0; i < sp.size(); ++i)
    s.spring[i] = field.weights(0.5 * (x_frame.col(sp.a[i]) + x_frame.col(sp.b[i])).head<2>());
  s.bend.resize(static_cast<size_t>(model.bending.size()));
  for (int e = 0; e < model.bending.size(); ++e)
    s.bend[e] = field.weights(x_frame.col(model.bending.v[e][1]).head<2>());
  return s;
}

void apply_density(Membrane& m, const DensitySites& sites, const Eigen::VectorXd& rho) {
  Model& model = m.sheet.model;
  for (int s = 0; s < model.springs.size(); ++s) {
    if (model.springs.family[s] == SpringFamily::added) continue;
    set_spring_fraction(m, s, fraction(sites.spring[s], rho));
  }
  for (int e = 0; e < model.bending.size(); ++e)
    set_bend_fraction(m, e, fraction(sites.bend[e], rho));
}

Eigen::VectorXd density_force_sensitivity(const Membrane& m, const DensitySites& sites,
                                          const Points& x, const Points& w) {
  const ElementRates r = element_force_sensitivity(m, x, w);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(sites.cells);
  const Springs& sp = m.sheet.model.springs;
  for (int s = 0; s < sp.size(); ++s)
    if (sp.family[s] != SpringFamily::added) spread(sites.spring[s], r.spring[s], out);
  for (int e = 0; e < m.sheet.model.bending.size(); ++e) spread(sites.bend[e], r.bend[e], out);
  return out;
}

DensityMap::DensityMap(DensityField field, DensitySites sites)
    : field_(std::move(field)), sites_(std::move(sites)) {}

void DensityMap::apply(Membrane& m, const Eigen::VectorXd& rho) const {
  apply_density(m, sites_, rho);
}

Eigen::VectorXd DensityMap::pull_back(const Membrane& m, const Eigen::VectorXd&, const Points& x,
                                      const Points& w) const {
  return density_force_sensitivity(m, sites_, x, w);
}

double DensityMap::regularization(const Eigen::VectorXd& rho, double weight,
                                  Eigen::VectorXd* gradient) const {
  const int nx = field_.nx, ny = field_.ny;
  const int pairs = (nx - 1) * ny + nx * (ny - 1);
  *gradient = Eigen::VectorXd::Zero(rho.size());
  if (pairs == 0 || weight == 0.0) return 0.0;
  const double w = weight / pairs;
  double sum = 0.0;
  auto pair = [&](int a, int b) {
    const double d = rho[a] - rho[b];
    sum += w * d * d;
    (*gradient)[a] += 2.0 * w * d;
    (*gradient)[b] -= 2.0 * w * d;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx) pair(i + nx * j, i + 1 + nx * j);
      if (j + 1 < ny) pair(i + nx * j, i + nx * (j + 1));
    }
  return sum;
}

}  // namespace membra
