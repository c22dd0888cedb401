#pragma once
// Which face of the sheet carries each piece of a bilayer stencil (`"resin_side": "convex"`,
// docs/inverse_design.md). A coat on one face keeps its stretched length while the latex beneath
// shrinks, so the composite curls with the coat on its convex side (docs/process.md "Bilayer"):
// a piece goes on top where the target bulges up and underneath where it sags.
#include "membra/design/target_surface.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

// +1 (top) or -1 (bottom) for a piece centred at frame point p (m): the sign of the target's
// mean curvature there, from the Laplacian of its height by central differences `step` (m, on
// the frame) apart. The frame is laid over the target's footprint axis by axis, its centre on
// the footprint's. Where the target is flat to within round-off, the top.
int convex_face(const TargetSurface& target, const Box2& frame, const Vec2& p, double step);

}  // namespace membra
