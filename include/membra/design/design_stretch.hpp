#pragma once
// The pre-stretch as a design variable (`"design": {"search_stretch": true}`,
// docs/inverse_design.md): a coat's curl and the metric a density makes both scale with the
// misfit 1 - 1/lambda, so the pattern search may move the stretch too.
#include "membra/design/design_spec.hpp"

namespace membra {

// The design with its stretch scaled along each axis, lambda' = 1 + factor (lambda - 1): the
// natural sheet becomes frame / lambda' (on a grid of square cells, design.resolution along its
// shorter side) and the stretch step takes it to the same frame, so stencils keep their place.
DesignSpec with_stretch(const DesignSpec& spec, double factor);
// lambda' = 1 + factor (lambda - 1), along each axis.
Vec2 stretched_lambda(const Vec2& lambda, double factor);

}  // namespace membra
