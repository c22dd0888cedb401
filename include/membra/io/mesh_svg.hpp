#pragma once
// The continuum sheet's mesh as an SVG drawing of the natural sheet, true scale in mm: every
// triangle outlined, the resin's filled, so a user sees where the mesh spends its elements.
#include <ostream>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

// `resin` marks the triangles to fill (one per triangle, or empty for none); width and height
// (m) the sheet's.
void write_mesh_svg(std::ostream& out, const Points& positions,
                    const std::vector<Triangle>& triangles, const std::vector<bool>& resin,
                    double width, double height);

}  // namespace membra
