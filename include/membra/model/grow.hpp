#pragma once
// Intrinsic deformation (the paper's experiments 4 and 5): the latex's natural lengths change by
// a factor that varies over the sheet, so its flat shape no longer fits and it finds a curved
// form. A factor f scales lengths along `direction`: isotropically (the metric times f^2), along a
// paper axis, or radially / around a centre (lengths across that direction keep their value).
#include <functional>
#include <optional>
#include <vector>

#include "membra/model/elements/springs.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

enum class GrowDirection { all, x, y, radial, hoop };

struct GrowSpec {
  std::function<double(const Vec2&)> factor;  // at a paper position (m); must be > 0
  std::optional<SpringFamily> family;         // only this family (all springs when empty)
  GrowDirection direction = GrowDirection::all;
  Vec2 center = Vec2::Zero();  // paper position (m) for radial and hoop
  PatternPtr region;           // paper coordinates; nullptr: the whole sheet
};

// Length ratio of every spring: the factor at the spring's paper midpoint, applied along the
// direction (a spring of paper vector d becomes sqrt((f d.u)^2 + (d.v)^2) / |d| times longer,
// u the direction, v across it), blended by the share of the spring inside the region.
// Throws std::invalid_argument if the factor is not a positive finite number somewhere.
std::vector<double> growth_ratios(const Membrane& m, const GrowSpec& spec);

// Multiplies the latex's natural (and release-path) lengths by ratio^exponent, so a growth can be
// applied in increments along a path. The cured resin keeps its length.
void apply_growth(Membrane& m, const std::vector<double>& ratios, double exponent);

}  // namespace membra
