#pragma once
// The resin stencil at true scale from the pattern's own geometry (model/pattern_stencil.hpp):
// SVG (for laser cutters and illustration tools) and DXF (for CAD/CAM), in mm, with the frame.
#include <ostream>
#include <vector>

#include "membra/model/pattern_stencil.hpp"

namespace membra {

// Resin filled black in the group "resin", the frame as a red hairline. Each loop is its own
// element: a polygon as a <polygon> of its corners, a whole ellipse as an <ellipse>, a loop of
// segments and arcs as a <path> with elliptical arcs; when the resin has holes, all its loops
// form one <path> (nonzero rule: holes run the other way). `frame` in m; SVG's y axis points
// down, so y is flipped about the frame. `underside`: the pieces coated on the bottom face of a
// stencil for both faces, filled blue (group "resin_bottom"), as seen from the top.
void write_svg(std::ostream& out, const std::vector<CurveLoop>& outlines, const Box2& frame,
               const std::vector<CurveLoop>& underside = {});

// DXF R2000, units mm: closed LWPOLYLINEs for polygons, ELLIPSE entities for ellipses and their
// arcs (a loop of both is drawn as its open polylines and arcs, end to end), on layer RESIN
// (RESIN_BOTTOM for the underside's), the frame on layer FRAME.
void write_dxf(std::ostream& out, const std::vector<CurveLoop>& outlines, const Box2& frame,
               const std::vector<CurveLoop>& underside = {});

}  // namespace membra
