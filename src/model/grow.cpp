#include "membra/model/grow.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "membra/core/units.hpp"

namespace membra {
namespace {

// The share of the element's outline inside the region: a spring's segment, a polygon's edges.
double share_inside(const Pattern& region, std::span<const Vec2> p) {
  if (p.size() == 2) return fraction_inside(region, p[0], p[1]);
  double sum = 0.0;
  for (size_t k = 0; k < p.size(); ++k) sum += fraction_inside(region, p[k], p[(k + 1) % p.size()]);
  return sum / static_cast<double>(p.size());
}

Vec2 centre_of(std::span<const Vec2> p) {
  if (p.size() == 2) return 0.5 * (p[0] + p[1]);
  Vec2 c = Vec2::Zero();
  for (const Vec2& q : p) c += q;
  return c / static_cast<double>(p.size());
}

}  // namespace

LocalGrowth PatternGrowth::at(std::span<const int>, std::span<const Vec2> paper,
                              std::string_view group) const {
  if (spec_.family && to_string(*spec_.family) != group) return {};
  const Vec2 mid = centre_of(paper);
  double f = spec_.factor(mid);
  if (!std::isfinite(f) || !(f > 0.0)) {
    std::ostringstream msg;
    msg << "the growth factor is " << f << " at (" << mid.x() / units::mm << ", "
        << mid.y() / units::mm << ") mm; it must be a positive number everywhere";
    throw std::invalid_argument(msg.str());
  }
  if (spec_.region) f = 1.0 + share_inside(*spec_.region, paper) * (f - 1.0);
  LocalGrowth g;
  g.factor = f;
  switch (spec_.direction) {
    case GrowDirection::all:
      return g;
    case GrowDirection::x:
      g.direction = Vec2(1.0, 0.0);
      break;
    case GrowDirection::y:
      g.direction = Vec2(0.0, 1.0);
      break;
    case GrowDirection::radial:
    case GrowDirection::hoop: {
      const Vec2 r = mid - spec_.center;
      // At the centre itself the direction is undefined: grow isotropically there.
      if (r.norm() < 1e-9 * (paper[1] - paper[0]).norm()) return g;
      g.direction = r.normalized();
      if (spec_.direction == GrowDirection::hoop)
        g.direction = Vec2(-g.direction.y(), g.direction.x());
      break;
    }
  }
  g.isotropic = false;
  return g;
}

GrowthPlan plan_growth(const Model& model, const GrowthField& field) {
  GrowthPlan plan;
  model.for_each_set(
      [&](const auto& set) { plan.per_set.push_back(set.growth(field, model.reference)); });
  return plan;
}

void apply_growth(Membrane& m, const GrowthPlan& plan, double exponent) {
  Model& model = m.sheet.model;
  const ReleaseLevel release = m.release();
  size_t k = 0;
  model.for_each_set(
      [&](auto& set) { set.grow(plan.per_set[k++], model.reference, exponent, release); });
}

}  // namespace membra
