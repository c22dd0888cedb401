#include "membra/design/resin_map.hpp"

#include "membra/model/elements/bend_kernel.hpp"

namespace membra {
void set_spring_fraction(Membrane& m, int s, double f) {
  Springs& sp = m.sheet.model.springs;
  sp.resin_fraction[s] = f;
  sp.update(s, m.release());
}

void set_bend_fraction(Membrane& m, int e, double f) {
  m.sheet.model.bending.set_fraction(e, f);
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
    const SpringRate r = sp.rate(s, m.release());
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
    out.bend[e] = b.rate(e) * work;
  }
  return out;
}

}  // namespace membra
