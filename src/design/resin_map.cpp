#include "membra/design/resin_map.hpp"

#include "membra/model/bend_kernel.hpp"

namespace membra {
namespace {

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

void set_spring_fraction(Membrane& m, int s, double f) {
  m.resin_fraction[s] = f;
  update_spring(m, s);
}

void set_bend_fraction(Membrane& m, int e, double f) {
  const double cl = m.latex_bending[e];
  m.bending_fraction[e] = f;
  m.sheet.model.bending.stiffness[e] = 1.0 / ((1.0 - f) / cl + f / (cl + m.resin_bending[e]));
}

ElementRates element_force_sensitivity(const Membrane& m, const Points& x, const Points& w) {
  const Model& model = m.sheet.model;
  const Springs& sp = model.springs;
  ElementRates out;
  out.spring = Eigen::VectorXd::Zero(sp.size());
  for (int s = 0; s < sp.size(); ++s) {
    if (sp.family[s] == SpringFamily::added) continue;
    const Vec3 d = x.col(sp.b[s]) - x.col(sp.a[s]);
    const double l = d.norm();
    if (l <= 0.0) continue;
    // grad E . w = k (l - l0) dl, dl = n . (w_b - w_a); its derivative in f.
    const double dl = d.dot(w.col(sp.b[s]) - w.col(sp.a[s])) / l;
    const SpringRate r = spring_rate(m, s, sp.stiffness[s]);
    out.spring[s] = (r.dk * (l - sp.rest_length[s]) - sp.stiffness[s] * r.dl0) * dl;
  }
  const Bending& b = model.bending;
  out.bend = Eigen::VectorXd::Zero(b.size());
  for (int e = 0; e < b.size(); ++e) {
    const auto& v = b.v[e];
    // The element's energy is linear in its stiffness c: grad E . w = c (grad E1 . w).
    const BendEval unit = bend_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), 1.0);
    double work = 0.0;
    for (int i = 0; i < 3; ++i) work += unit.grad[i].dot(w.col(v[i]));
    const double c = b.stiffness[e], cl = m.latex_bending[e];
    out.bend[e] = c * c * (1.0 / cl - 1.0 / (cl + m.resin_bending[e])) * work;
  }
  return out;
}

}  // namespace membra
