#pragma once
// Intrinsic deformation (the paper's experiments 4 and 5): the latex's natural lengths change by
// a factor that varies over the sheet, so its flat shape no longer fits and it finds a curved
// form. A factor f scales lengths along `direction`: isotropically (the metric times f^2), along a
// paper axis, or radially / around a centre (lengths across that direction keep their value).
// Every element set applies the growth by its own rule (set_context.hpp's GrowthField).
#include <functional>
#include <optional>
#include <vector>

#include "membra/model/elements/set_context.hpp"
#include "membra/model/elements/springs.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

enum class GrowDirection { all, x, y, radial, hoop };

struct GrowSpec {
  std::function<double(const Vec2&)> factor;  // at a paper position (m); must be > 0
  std::optional<SpringFamily> family;         // only this spring family (every element if empty)
  GrowDirection direction = GrowDirection::all;
  Vec2 center = Vec2::Zero();  // paper position (m) for radial and hoop
  PatternPtr region;           // paper coordinates; nullptr: the whole sheet
};

// A grow step's field: the factor at the element's paper centre, along the direction, blended by
// the share of the element's outline inside the region (a spring's segment, a triangle's edges).
class PatternGrowth final : public GrowthField {
 public:
  explicit PatternGrowth(GrowSpec spec) : spec_(std::move(spec)) {}
  LocalGrowth at(std::span<const int> ids, std::span<const Vec2> paper,
                 std::string_view group) const override;

 private:
  GrowSpec spec_;
};

// Each set's growth of each of its elements, in Model::for_each_set's order: read once when a
// step begins, applied in shares along its path.
struct GrowthPlan {
  std::vector<std::vector<LocalGrowth>> per_set;
};

// Throws std::invalid_argument if the growth is not a positive finite factor somewhere.
GrowthPlan plan_growth(const Model& model, const GrowthField& field);

// Applies the plan raised to `exponent` to the latex's natural (and release-path) rest state of
// every set, so a growth can be applied in increments along a path. The cured resin keeps its
// rest state.
void apply_growth(Membrane& m, const GrowthPlan& plan, double exponent);

}  // namespace membra
