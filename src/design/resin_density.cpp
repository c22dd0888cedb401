#include "membra/design/resin_density.hpp"

#include <algorithm>

#include "membra/model/bend_kernel.hpp"

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

// d/df of a spring's stiffness and rest length under the composite rule (update_spring): the
// resin part (resin and latex in parallel) in series with the latex part.
struct SpringRate {
  double dk = 0.0, dl0 = 0.0;
};
SpringRate spring_rate(const Membrane& m, int s, double k) {
  const double kl = m.latex_stiffness[s], kr = m.resin_stiffness[s];
  const double l_nat = m.natural_length[s];
  const double latex_rest =
      m.releasing ? l_nat + m.release_level * (m.frame_length[s] - l_nat) : l_nat;
  const double k_in = kr + kl;
  const double rest_in = (kr * m.resin_length[s] + kl * latex_rest) / k_in;
  return {k * k * (1.0 / kl - 1.0 / k_in), rest_in - latex_rest};
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
    m.resin_fraction[s] = fraction(sites.spring[s], rho);
    update_spring(m, s);
  }
  for (int e = 0; e < model.bending.size(); ++e) {
    const double f = fraction(sites.bend[e], rho), cl = m.latex_bending[e];
    m.bending_fraction[e] = f;
    model.bending.stiffness[e] = 1.0 / ((1.0 - f) / cl + f / (cl + m.resin_bending[e]));
  }
}

Eigen::VectorXd density_force_sensitivity(const Membrane& m, const DensitySites& sites,
                                          const Points& x, const Points& w) {
  const Model& model = m.sheet.model;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(sites.cells);
  const Springs& sp = model.springs;
  for (int s = 0; s < sp.size(); ++s) {
    if (sp.family[s] == SpringFamily::added) continue;
    const Vec3 d = x.col(sp.b[s]) - x.col(sp.a[s]);
    const double l = d.norm();
    if (l <= 0.0) continue;
    // grad E . w = k (l - l0) dl, dl = n . (w_b - w_a); its derivative in f.
    const double dl = d.dot(w.col(sp.b[s]) - w.col(sp.a[s])) / l;
    const SpringRate r = spring_rate(m, s, sp.stiffness[s]);
    spread(sites.spring[s], (r.dk * (l - sp.rest_length[s]) - sp.stiffness[s] * r.dl0) * dl, out);
  }
  const Bending& b = model.bending;
  for (int e = 0; e < b.size(); ++e) {
    const auto& v = b.v[e];
    // The element's energy is linear in its stiffness c: grad E . w = c (grad E1 . w).
    const BendEval unit = bend_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), 1.0);
    double work = 0.0;
    for (int i = 0; i < 3; ++i) work += unit.grad[i].dot(w.col(v[i]));
    const double c = b.stiffness[e], cl = m.latex_bending[e];
    const double dc = c * c * (1.0 / cl - 1.0 / (cl + m.resin_bending[e]));
    spread(sites.bend[e], dc * work, out);
  }
  return out;
}

}  // namespace membra
