#include "membra/measure/stress_concentration.hpp"

#include <algorithm>
#include <limits>

namespace membra {

StressConcentration stress_concentration(const Model& model, const std::vector<double>& stress,
                                         const StressFeature& feature, double near, double far) {
  StressConcentration r{feature.name, feature.kind};
  std::vector<double> far_values;
  bool any_near = false;
  for (int p = 0; p < model.num_particles(); ++p) {
    const Vec2 q = model.reference.col(p).head<2>();
    double d = std::numeric_limits<double>::infinity();
    for (const Vec2& w : feature.where) d = std::min(d, (q - w).norm());
    if (d <= near && (!any_near || stress[p] > r.peak_stress)) {
      r.peak_stress = stress[p];
      r.peak_at = q;
      any_near = true;
    }
    if (d >= far) far_values.push_back(stress[p]);
  }
  if (!far_values.empty()) {
    auto mid = far_values.begin() + static_cast<long>(far_values.size() / 2);
    std::nth_element(far_values.begin(), mid, far_values.end());
    r.far_field_stress = *mid;
  }
  if (r.far_field_stress > 0.0) r.concentration = r.peak_stress / r.far_field_stress;
  return r;
}

}  // namespace membra
