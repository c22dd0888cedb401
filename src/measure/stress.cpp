#include "membra/measure/stress.hpp"

#include <algorithm>

namespace membra {

namespace {

// Widens [lo, hi] to v; the first value sets both.
void widen(bool& first, double& lo, double& hi, double v) {
  lo = first ? v : std::min(lo, v);
  hi = first ? v : std::max(hi, v);
  first = false;
}

}  // namespace

StressRanges stress_ranges(const Model& model, const Points& x, double thickness) {
  StressRanges r;
  bool first_stress = true, first_strain = true, first_force = true;
  model.for_each_set([&](const auto& set) {
    for (int i = 0; i < set.size(); ++i) {
      const ElementStress e = set.stress(i, x, thickness);
      if (e.strained) widen(first_strain, r.min_strain, r.max_strain, e.strain);
      if (e.axial) widen(first_force, r.min_force, r.max_force, e.force);
      if (e.carries) widen(first_stress, r.min_stress, r.max_stress, e.stress);
    }
  });
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
