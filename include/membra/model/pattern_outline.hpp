#pragma once
// Outlines of a pattern, for the laser-cut stencil: closed polygons traced where the pattern's
// field crosses zero (marching squares with linear interpolation), clipped to the frame.
#include <vector>

#include "membra/model/pattern.hpp"

namespace membra {

using Polygon2 = std::vector<Vec2>;  // closed: the last vertex connects to the first

// Traces the outline of `pattern` inside `frame` (m) on a grid of cells of size `step` (m).
// Outer boundaries run counter-clockwise and holes clockwise (resin on the left), so the sum
// of signed areas is the resin area.
std::vector<Polygon2> trace_outlines(const Pattern& pattern, const Box2& frame, double step);

// Signed area of a polygon (positive counter-clockwise), m^2.
double signed_area(const Polygon2& polygon);

}  // namespace membra
