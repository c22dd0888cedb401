#pragma once
// The stencil's outline drawn from the pattern's own geometry (docs/outputs.md, "The stencil"):
// polygons as given, ellipses as elliptical arcs, and unions and differences as the pieces of
// their parts' outlines that bound the whole. Primitives with no exact form (strips, rings,
// hyperbola bands, images) are traced as pattern_boundaries does, to the stencil's chord
// tolerance of 5 um (a laser's kerf is some 100 um) or to the one the caller gives (the mesh's).
#include <vector>

#include "membra/geometry/plane_curve.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/pattern_boundary.hpp"

namespace membra {

// A closed loop of segments and arcs, each starting where the one before ends, resin on its left
// (outer boundaries counter-clockwise, holes clockwise).
using CurveLoop = std::vector<PlaneCurve>;

inline constexpr BoundaryOptions kStencilTracing{5e-6, 2.5e-4};

// The outline of the pattern's resin inside `frame` (clipped to it).
std::vector<CurveLoop> stencil_outline(const Pattern& pattern, const Box2& frame,
                                       const BoundaryOptions& options = kStencilTracing);

// Signed area a loop encloses (positive counter-clockwise), m^2: exact for arcs.
double loop_area(const CurveLoop& loop);

}  // namespace membra
