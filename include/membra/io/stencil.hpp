#pragma once
// The resin stencil at true scale: SVG (for laser cutters and illustration tools) and DXF
// (R12, for CAD/CAM), in mm, with the frame outline.
#include <ostream>
#include <vector>

#include "membra/model/pattern_outline.hpp"

namespace membra {

// Resin regions filled black (nonzero rule: holes run the other way), the frame as a red
// hairline. `frame` in m; SVG's y axis points down, so y is flipped about the frame. `underside`:
// the pieces coated on the bottom face of a stencil for both faces, filled blue (path
// "resin_bottom"), as seen from the top.
void write_svg(std::ostream& out, const std::vector<Polygon2>& outlines, const Box2& frame,
               const std::vector<Polygon2>& underside = {});

// Closed POLYLINE entities on layer RESIN (RESIN_BOTTOM for the underside's) and the frame on
// layer FRAME, units mm.
void write_dxf(std::ostream& out, const std::vector<Polygon2>& outlines, const Box2& frame,
               const std::vector<Polygon2>& underside = {});

}  // namespace membra
