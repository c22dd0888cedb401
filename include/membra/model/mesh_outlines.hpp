#pragma once
// The polygons a continuum mesh follows (docs/model.md, "Meshes that follow the pattern"): the
// pattern's exact outline as the stencil draws it (polygons with their own vertices, ellipses as
// arcs, unions and differences as the pieces of their parts' outlines that bound the whole), the
// arcs sampled to the chord tolerance, and vertices within the tolerance of the chords between
// those kept dropped (Douglas-Peucker). Primitives with no exact form (strips,
// rings, hyperbola bands, images) are traced as pattern_boundaries does.
#include <vector>

#include "membra/geometry/plane_curve.hpp"
#include "membra/model/pattern_boundary.hpp"

namespace membra {

// Points along the curve from its start up to (not including) its end: a segment gives its
// start; an arc is cut until no chord strays more than `tolerance` (m) from it.
std::vector<Vec2> sample_curve(const PlaneCurve& curve, double tolerance);

// The pattern's outlines inside `frame` (clipped to it) as closed polygons, resin on their left.
// Falls back to pattern_boundaries when the exact outline does not close (two ellipses crossing
// closer than the intersection search resolves).
std::vector<Polygon2> mesh_outlines(const Pattern& pattern, const Box2& frame,
                                    const BoundaryOptions& options = {});

}  // namespace membra
