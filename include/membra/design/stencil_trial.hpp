#pragma once
// One stencil tried for a design: laid out from a density, simulated with the ordinary runner
// (a typed scene, no file in the loop) and compared with the target after rigid alignment — the
// step both design methods end in (docs/inverse_design.md).
#include <functional>
#include <limits>
#include <string>

#include "membra/design/design_result.hpp"
#include "membra/process/run.hpp"

namespace membra {

// The scene that simulates `stencil` for a design: spec.scene with the stencil as its resin
// (without the impregnate step when the stencil is empty).
Scene stencil_scene(const DesignSpec& spec, const Stencil& stencil);

// A stencil laid out from `density` (frame coordinates), simulated as `membra run` would and
// compared with the target after rigid alignment.
struct StencilTrial {
  Stencil stencil;
  Scene scene;
  RunResult run;
  ShapeError error;
  double rms = std::numeric_limits<double>::infinity();  // % of the target's diameter
  double max = std::numeric_limits<double>::infinity();
  std::string note;  // why it is not a prediction ("did not converge", ...); empty if it is
};
StencilTrial try_stencil(const DesignSpec& spec, const TargetSurface& target,
                         const std::function<double(const Vec2&)>& density);
// The stencil a design lays out from `density`: cells inside the target's outline, each piece
// on its face.
Stencil design_stencil(const DesignSpec& spec, const TargetSurface& target,
                       const std::function<double(const Vec2&)>& density);
// The same for a stencil already laid out.
StencilTrial simulate_stencil(const DesignSpec& spec, const TargetSurface& target, Stencil stencil);
// The trial as an entry of the design's history (stage "stencil"; not yet marked best).
DesignIteration trial_iteration(const StencilTrial& trial, int index, double seconds);
// Makes the trial the design's result: its scene, stencil, run, error and errors in %.
void adopt_stencil(StencilTrial&& trial, DesignResult& r);

}  // namespace membra
