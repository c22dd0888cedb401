#pragma once
// Inverse design by pattern search (`"method": "pattern_search"`, docs/inverse_design.md): a
// resin density with three parameters — mean, radial gradient, x/y anisotropy — started from
// mechanics (r.start) and a few plain starts, laid out as a stencil and simulated for every
// trial, each parameter moved up and down by its step, the steps halved when nothing helps, until
// they are small or the budget is spent.
#include <functional>

#include "membra/design/design_result.hpp"

namespace membra {

// Fills `r` (whose target, reachability, flat error and start are set) with the best stencil.
void design_by_pattern_search(const DesignSpec& spec, DesignResult& r,
                              const std::function<void(const DesignIteration&)>& progress);

}  // namespace membra
