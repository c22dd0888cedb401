#include "membra/model/added_springs.hpp"

#include <stdexcept>

namespace membra {

int add_springs(Membrane& m, const AddSpringsSpec& spec) {
  if (!spec.region) throw std::invalid_argument("add_springs: no region");
  if (spec.count < 1) throw std::invalid_argument("add_springs: count must be >= 1");
  if (!(spec.stiffness > 0.0)) throw std::invalid_argument("add_springs: stiffness must be > 0");
  if (!(spec.rest_factor > 0.0))
    throw std::invalid_argument("add_springs: rest factor must be > 0");
  Springs& sp = m.sheet.model.springs;
  const Points& x = m.state.x;
  const int lattice = sp.size();
  int pairs = 0;
  for (int s = 0; s < lattice; ++s) {
    if (sp.family[s] == SpringFamily::added) continue;
    if (spec.along && sp.family[s] != *spec.along) continue;
    if (fraction_inside(*spec.region, x.col(sp.a[s]).head<2>(), x.col(sp.b[s]).head<2>()) < 0.5)
      continue;
    const double length = (x.col(sp.b[s]) - x.col(sp.a[s])).norm();
    const double rest = spec.rest_factor * length, k = spec.count * spec.stiffness;
    sp.add(sp.a[s], sp.b[s], rest, k, sp.damping[s], SpringFamily::added);
    ++pairs;
  }
  return pairs * spec.count;
}

void set_added_springs_level(Membrane& m, int first_spring, const std::vector<double>& start_length,
                             double rest_factor, double level) {
  Springs& sp = m.sheet.model.springs;
  for (size_t i = 0; i < start_length.size(); ++i) {
    const int s = first_spring + static_cast<int>(i);
    const double rest = start_length[i] * (1.0 + level * (rest_factor - 1.0));
    sp.natural_length[s] = sp.resin_length[s] = sp.frame_length[s] = rest;
    sp.rest_length[s] = rest;
  }
}

}  // namespace membra
