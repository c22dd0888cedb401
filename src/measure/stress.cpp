#include "membra/measure/stress.hpp"

#include <algorithm>

namespace membra {

SpringStress spring_stress(const Model& model, const Points& x, double thickness) {
  const Springs& sp = model.springs;
  SpringStress r;
  const size_t n = static_cast<size_t>(sp.size());
  r.strain.resize(n);
  r.force.resize(n);
  r.stress.assign(n, 0.0);
  bool first = true;
  for (int i = 0; i < sp.size(); ++i) {
    const double l = (x.col(sp.b[i]) - x.col(sp.a[i])).norm(), l0 = sp.rest_length[i];
    r.strain[i] = l0 > 0.0 ? (l - l0) / l0 : 0.0;
    r.force[i] = sp.stiffness[i] * (l - l0);
    r.min_strain = i == 0 ? r.strain[i] : std::min(r.min_strain, r.strain[i]);
    r.max_strain = i == 0 ? r.strain[i] : std::max(r.max_strain, r.strain[i]);
    r.min_force = i == 0 ? r.force[i] : std::min(r.min_force, r.force[i]);
    r.max_force = i == 0 ? r.force[i] : std::max(r.max_force, r.force[i]);
    if (!(sp.width[i] > 0.0) || !(thickness > 0.0)) continue;
    r.stress[i] = r.force[i] / (sp.width[i] * thickness);
    r.min_stress = first ? r.stress[i] : std::min(r.min_stress, r.stress[i]);
    r.max_stress = first ? r.stress[i] : std::max(r.max_stress, r.stress[i]);
    first = false;
  }
  return r;
}

std::vector<double> vertex_stress(const Model& model, const Points& x, double thickness) {
  std::vector<double> sum(static_cast<size_t>(model.num_particles()), 0.0);
  std::vector<int> count(sum.size(), 0);
  model.for_each_set([&](const auto& set) {
    for (int i = 0; i < set.size(); ++i) {
      const ElementStress e = set.stress(i, x, thickness);
      if (!e.carries) continue;
      for (int p : set.ids(i)) sum[p] += e.stress, ++count[p];
    }
  });
  for (size_t p = 0; p < sum.size(); ++p)
    if (count[p] > 0) sum[p] /= count[p];
  return sum;
}

}  // namespace membra
