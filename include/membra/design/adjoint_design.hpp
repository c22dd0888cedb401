#pragma once
// Inverse design by densities and the adjoint (`"design": {"method": "adjoint"}`,
// docs/inverse_design.md):
//  1. metric: every particle's point on the target (the frame scaled onto the footprint) and
//     the density whose uniform release gives the target's stretch at each cell; where that
//     density falls outside [0, 1] the target cannot be reached there (reported per cell);
//  2. physics: the densities per cell optimised with bounded L-BFGS on the aligned distance to
//     those points, gradients by the adjoint of the released equilibrium, every equilibrium
//     warm-started and a stable minimum;
//  3. fabrication: the densities laid out as a stencil of squares (design/stencil_layout.hpp)
//     and that stencil simulated from the flat start and compared with the target as the
//     pattern search compares its stencils, so the reported error is the stencil's.
#include <functional>

#include "membra/design/design_result.hpp"

namespace membra {

// Fills `r` (whose target, reachability and flat error are set) with the design.
void design_by_adjoint(const DesignSpec& spec, DesignResult& r,
                       const std::function<void(const DesignIteration&)>& progress);

}  // namespace membra
