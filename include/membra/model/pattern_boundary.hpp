#pragma once
// The outlines of a pattern traced, for the patterns with no exact form (strips, rings, hyperbola
// bands, images: mesh_outlines.hpp takes the others as drawn; docs/model.md, "Meshes that follow
// the pattern"): traced on a fine grid, each vertex moved onto the pattern's outline, straight
// runs merged to a chord tolerance, and the corners the tracing cut off restored where the two
// edges meet. Straight edges and polygon corners come out as given; curves as chords within the
// tolerance.
#include <vector>

#include "membra/model/pattern_outline.hpp"

namespace membra {

struct BoundaryOptions {
  double tolerance = 2e-5;  // m: how far a chord may stray from the outline
  double step = 2.5e-4;     // m: the tracing grid, finer than any feature to keep
};

// The pattern's outlines inside `frame` (clipped to it, so a pattern reaching the frame's edge
// closes along it). Outer boundaries counter-clockwise, holes clockwise, as trace_outlines.
std::vector<Polygon2> pattern_boundaries(const Pattern& pattern, const Box2& frame,
                                         const BoundaryOptions& options = {});

// A closed polygon with the vertices that stray less than `tolerance` from the chords between
// the kept ones removed (Douglas-Peucker).
Polygon2 simplify_closed(const Polygon2& polygon, double tolerance);

}  // namespace membra
