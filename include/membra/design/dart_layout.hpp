#pragma once
// Darts: a stencil for domes (`"resin": {"layout": "darts"}`, docs/inverse_design.md "Darts").
// The whole sheet is resin except a few wedge-shaped gaps of bare latex pointing at its centre,
// like a dressmaker's darts. On release the resin keeps its stretched size, so lengths along
// the spokes between the darts stay; the latex in the darts shrinks, so every circle about the
// centre gets shorter, by more the wider the darts are there. A circle shorter than 2 pi times
// its distance from the centre is what a dome's metric is: the darts' widths are read off the
// target's geodesic polar coordinates. The latex in the darts stays in tension, so nothing
// wrinkles, unlike stiff squares with latex around them (stencil_layout.hpp).
#include <functional>
#include <vector>

#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {

// The target's circumferential deficit along rays from its footprint's centre: at geodesic
// distance s along the ray in direction theta, 1 - |dX/dtheta| / s (0 on a plane, s^2 / 6R^2 near
// the pole of a sphere of radius R; negative where circles are longer than on a plane).
struct DartProfile {
  Vec2 centre = Vec2::Zero();     // m, target coordinates: where the rays start
  Vec2 footprint = Vec2::Zero();  // m, the target footprint's half-sides (laid over the frame's)
  int rays = 0;
  std::vector<std::vector<double>> s, deficit;  // per ray, per sample: m, and the deficit
  // m: the target's half-width measured along its surface (each ray's length along it, scaled
  // from where the ray leaves the footprint to the footprint's inscribed half-width; averaged).
  // Meaningful for a profile about the footprint's centre only.
  // A frame of twice this makes the darts' form at the target's size.
  double radius = 0.0;

  // The deficit on ray direction `theta` (radians) at `u` (0..1) of that ray's geodesic length.
  double at(double theta, double u) const;
};
DartProfile dart_profile(const TargetSurface& target, int rays = 72, int samples = 48);
// The same from another centre (inside the footprint): each ray runs to the footprint's edge.
DartProfile dart_profile(const TargetSurface& target, const Vec2& centre, int rays = 72,
                         int samples = 48);

// Where darts should centre on a target with several domes or hollows (`"dart_centres": "auto"`):
// the peaks of its Gaussian curvature (m, target coordinates from the footprint's centre), each
// positive, at least 0.3 of the highest, and standing out from its surroundings within
// `separation` by a quarter of its value (so a sphere's even curvature has none: one centre, the
// footprint's, serves it). At most 16, highest first.
std::vector<Vec2> curvature_peaks(const TargetSurface& target, double separation);

struct DartOptions {
  int darts = 6;
  double scale = 1.0;          // the darts' latex share over what the deficit asks (a calibration)
  double lambda = 1.5;         // the frame's pre-stretch (the latex shrinks by 1 - 1/lambda)
  double min_feature = 0.004;  // m: darts begin where they are this wide; spokes stay as wide
  // A coat on one face (bilayer): with `face` (a frame point -> +1 top, -1 bottom) the resin
  // goes on the face it names, decided cell by cell of `cell` (resin_face.hpp: "convex").
  std::function<int(const Vec2&)> face = {};
  double cell = 0.02;  // m
};

// The stencil on `frame` (the target's footprint laid over it, centre on centre, the frame's
// edge at the end of each ray): resin over the whole sheet (a disk on `disk` targets) less
// `darts` wedges about each profile's centre, each as wide at frame radius r as the mean deficit
// of its sector there asks, times the scale, over 1 - 1/lambda. Where the target asks for no
// shrink (deficit <= 0) a dart has no width. With several centres (a bump here, a hollow there),
// each centre's darts stay in the part of the sheet nearer to it than to any other (a Voronoi
// cell), min_feature / 2 short of its border.
Stencil layout_darts(const std::vector<DartProfile>& profiles, const Box2& frame, bool disk,
                     const DartOptions& options);

// Fisheye darts (`"layout": "fisheye_darts"`): double-pointed lenses of bare latex lying across
// a stretch along one axis, spaced evenly along it. A row along the stretch keeps the length of
// its resin and loses the shrink of its latex, so the release sets each row's length L(v) by its
// latex share at v, the distance across. Columns keep theirs (nothing shrinks across), and the
// metric dv^2 + L(v)^2 du^2 has the Gaussian curvature K = -L''/L: rows longer at the edges than
// in the middle make a saddle (K < 0), shorter ones a dome.
struct RowProfile {
  int axis = 0;                  // the stretch's axis: rows run along it (0: x, 1: y)
  std::vector<double> v, share;  // across, m from the centre, and the latex share L asks there
};
// The rows' lengths from the target's Gaussian curvature averaged along each row (angle defects
// over areas, in an odd number of bins across, the middle one on the centre): L'' = -K L from L =
// 1, L' = 0 at the centre; the latex share of a row is 1 - L / L_max (the longest rows are all
// resin), before the scale and the shrink.
RowProfile row_profile(const TargetSurface& target, int axis, int bins = 25);
// Lenses at `darts` positions along the axis, each as wide at v as its pitch times the scale
// times the share there over 1 - 1/lambda (lambda: the stretch along the axis); narrower than
// the minimum feature, none.
Stencil layout_fisheye_darts(const RowProfile& profile, const Box2& frame,
                             const DartOptions& options);

}  // namespace membra
