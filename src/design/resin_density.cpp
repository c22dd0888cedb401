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
  DensitySites s;
  s.cells = static_cast<int>(field.value.size());
  m.sheet.model.for_each_set([&](const auto& set) {
    auto& sites = s.set.emplace_back(static_cast<size_t>(set.size()));
    for (int i = 0; i < set.size(); ++i) {
      const ResinFootprint f = set.footprint(i, x_frame);
      if (f.count > 0) sites[static_cast<size_t>(i)] = {field.weights(f.site), true};
    }
  });
  return s;
}

void apply_density(Membrane& m, const DensitySites& sites, const Eigen::VectorXd& rho) {
  size_t k = 0;
  m.sheet.model.for_each_set([&](auto& set) {
    const auto& at = sites.set[k++];
    for (int i = 0; i < set.size(); ++i)
      if (at[static_cast<size_t>(i)].takes)
        set.set_resin_fraction(i, fraction(at[static_cast<size_t>(i)].weights, rho), m.release());
  });
}

Eigen::VectorXd density_force_sensitivity(const Membrane& m, const DensitySites& sites,
                                          const Points& x, const Points& w) {
  const ElementRates r = element_force_sensitivity(m, x, w);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(sites.cells);
  for (size_t k = 0; k < sites.set.size(); ++k)
    for (size_t i = 0; i < sites.set[k].size(); ++i)
      if (sites.set[k][i].takes)
        spread(sites.set[k][i].weights, r.set[k][static_cast<Eigen::Index>(i)], out);
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
