#pragma once
// Darts: a stencil for domes (`"resin": {"layout": "darts"}`, docs/inverse_design.md "Darts").
// The whole sheet is resin except a few wedge-shaped gaps of bare latex pointing at its centre,
// like a dressmaker's darts. On release the resin keeps its stretched size, so lengths along
// the spokes between the darts stay; the latex in the darts shrinks, so every circle about the
// centre gets shorter, by more the wider the darts are there. A circle shorter than 2 pi times
// its distance from the centre is what a dome's metric is: the darts' widths are read off the
// target's geodesic polar coordinates. The latex in the darts stays in tension, so nothing
// wrinkles, unlike stiff squares with latex around them (stencil_layout.hpp).
#include <vector>

#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {

// The target's circumferential deficit along rays from its footprint's centre: at geodesic
// distance s along the ray in direction theta, 1 - |dX/dtheta| / s (0 on a plane, s^2 / 6R^2 near
// the pole of a sphere of radius R; negative where circles are longer than on a plane).
struct DartProfile {
  int rays = 0;
  std::vector<std::vector<double>> s, deficit;  // per ray, per sample: m, and the deficit
  double mean_radius = 0.0;                     // m, the rays' geodesic length, averaged

  // The deficit on ray direction `theta` (radians) at `u` (0..1) of that ray's geodesic length.
  double at(double theta, double u) const;
};
DartProfile dart_profile(const TargetSurface& target, int rays = 72, int samples = 48);

struct DartOptions {
  int darts = 6;
  double scale = 1.0;          // the darts' latex share over what the deficit asks (a calibration)
  double lambda = 1.5;         // the frame's pre-stretch (the latex shrinks by 1 - 1/lambda)
  double min_feature = 0.004;  // m: darts begin where they are this wide; spokes stay as wide
};

// The stencil on `frame` (the target's footprint laid over it, centre on centre, the frame's
// half-width at the end of each ray): resin over the whole sheet (a disk on `disk` targets)
// less `darts` wedges, each as wide at frame radius r as the mean deficit of its sector there
// asks, times the scale, over 1 - 1/lambda. Where the target asks for no shrink (deficit <= 0)
// a dart has no width.
Stencil layout_darts(const DartProfile& profile, const Box2& frame, bool disk,
                     const DartOptions& options);

}  // namespace membra
