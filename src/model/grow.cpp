#include "membra/model/grow.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "membra/core/units.hpp"

namespace membra {

std::vector<double> growth_ratios(const Membrane& m, const GrowSpec& spec) {
  const Model& model = m.sheet.model;
  const Springs& sp = model.springs;
  std::vector<double> ratio(sp.size(), 1.0);
  for (int s = 0; s < sp.size(); ++s) {
    if (spec.family && sp.family[s] != *spec.family) continue;
    const Vec2 pa = model.reference.col(sp.a[s]).head<2>(),
               pb = model.reference.col(sp.b[s]).head<2>();
    const Vec2 mid = 0.5 * (pa + pb), d = pb - pa;
    double f = spec.factor(mid);
    if (!std::isfinite(f) || !(f > 0.0)) {
      std::ostringstream msg;
      msg << "the growth factor is " << f << " at (" << mid.x() / units::mm << ", "
          << mid.y() / units::mm << ") mm; it must be a positive number everywhere";
      throw std::invalid_argument(msg.str());
    }
    if (spec.region) f = 1.0 + fraction_inside(*spec.region, pa, pb) * (f - 1.0);
    Vec2 u = Vec2::Zero();
    switch (spec.direction) {
      case GrowDirection::all:
        ratio[s] = f;
        continue;
      case GrowDirection::x:
        u = Vec2(1.0, 0.0);
        break;
      case GrowDirection::y:
        u = Vec2(0.0, 1.0);
        break;
      case GrowDirection::radial:
      case GrowDirection::hoop: {
        const Vec2 r = mid - spec.center;
        // At the centre itself the direction is undefined: grow isotropically there.
        if (r.norm() < 1e-9 * d.norm()) {
          ratio[s] = f;
          continue;
        }
        u = r.normalized();
        if (spec.direction == GrowDirection::hoop) u = Vec2(-u.y(), u.x());
        break;
      }
    }
    const double along = d.dot(u), across = d.x() * u.y() - d.y() * u.x();
    ratio[s] = std::hypot(f * along, across) / d.norm();
  }
  return ratio;
}

void apply_growth(Membrane& m, const std::vector<double>& ratios, double exponent) {
  Springs& sp = m.sheet.model.springs;
  for (int s = 0; s < sp.size(); ++s) {
    if (ratios[s] == 1.0) continue;
    const double g = std::pow(ratios[s], exponent);
    sp.natural_length[s] *= g;
    sp.frame_length[s] *= g;
    sp.update(s, m.release());
  }
}

}  // namespace membra
