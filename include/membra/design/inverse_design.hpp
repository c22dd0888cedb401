#pragma once
// Inverse design (`membra design target FILE`): from a target surface to a resin stencil whose
// released form comes close to it (docs/inverse_design.md). The target is built, its area checked
// against what the pre-stretch allows and a start taken from mechanics; then the design file's
// method runs: the pattern search over three density parameters (design/pattern_search.hpp) or
// densities per cell by the adjoint (design/adjoint_design.hpp). The design file is read by
// io/design_reader.hpp.
#include <functional>

#include "membra/design/design_result.hpp"
#include "membra/design/design_spec.hpp"
#include "membra/design/stencil_trial.hpp"

namespace membra {

// Runs the design. `progress` (optional) is told of every forward simulation (and, with the
// adjoint method, of every density iterate).
DesignResult run_design(const DesignSpec& spec,
                        const std::function<void(const DesignIteration&)>& progress = {});

}  // namespace membra
