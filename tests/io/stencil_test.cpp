// The stencil's SVG and DXF, drawn from the pattern's geometry at true scale.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "membra/io/scene.hpp"
#include "membra/io/stencil.hpp"

namespace membra {
namespace {

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The synclastic ellipse example: one ellipse and 24 squares, each written as itself.
TEST(Stencil, TheEllipseExampleIsAnEllipseAndItsSquares) {
  const Scene scene =
      load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/synclastic_ellipse.json");
  const PatternPtr pattern = scene_pattern(scene);
  ASSERT_TRUE(pattern);
  const Box2 frame = scene_frame(scene);
  const auto loops = stencil_outline(*pattern, frame);
  std::ostringstream svg;
  write_svg(svg, loops, frame);
  const std::string s = svg.str();
  EXPECT_NE(s.find("width=\"300.0000mm\""), std::string::npos);
  EXPECT_EQ(occurrences(s, "<ellipse "), 1u);
  EXPECT_NE(s.find("<ellipse cx=\"150.0000\" cy=\"100.0000\" rx=\"120.0000\" ry=\"80.0000\"/>"),
            std::string::npos);
  EXPECT_EQ(occurrences(s, "<polygon "), 24u);
  EXPECT_EQ(occurrences(s, "<path "), 0u);
  // Every polygon has its four corners: three spaces between four "x,y" pairs.
  for (size_t at = s.find("<polygon points=\""); at != std::string::npos;
       at = s.find("<polygon points=\"", at + 1)) {
    const std::string points = s.substr(at + 17, s.find('"', at + 17) - at - 17);
    EXPECT_EQ(occurrences(points, ","), 4u) << points;
  }
  std::ostringstream dxf;
  write_dxf(dxf, loops, frame);
  EXPECT_EQ(occurrences(dxf.str(), "\nELLIPSE\n"), 1u);
  EXPECT_EQ(occurrences(dxf.str(), "\nLWPOLYLINE\n"), 25u);          // the squares and the frame
  EXPECT_NE(dxf.str().find("$INSUNITS\n70\n4"), std::string::npos);  // millimetres
}

// Holes need one path (nonzero rule); arcs in it are SVG arcs, and DXF ellipse arcs.
TEST(Stencil, ResinWithHolesIsOnePathOfArcs) {
  const Box2 frame{Vec2::Zero(), Vec2(0.2, 0.2)};
  const auto plate = make_difference({make_ellipse({0.1, 0.1}, 0.05, 0.03, 0.3),
                                      make_ellipse({0.1, 0.1}, 0.01, 0.01, 0.0),
                                      make_ellipse({0.15, 0.1}, 0.02, 0.02, 0.0)});
  const auto loops = stencil_outline(*plate, frame);
  ASSERT_EQ(loops.size(), 2u);  // the bitten plate and its hole
  std::ostringstream svg, dxf;
  write_svg(svg, loops, frame);
  EXPECT_EQ(occurrences(svg.str(), "<path "), 1u);
  EXPECT_EQ(occurrences(svg.str(), "<ellipse "), 0u);
  EXPECT_GE(occurrences(svg.str(), " A"), 4u);  // the hole in two halves, and the plate's arcs
  write_dxf(dxf, loops, frame);
  EXPECT_EQ(occurrences(dxf.str(), "\nELLIPSE\n"), 3u);     // the hole, the plate's arc, the bite's
  EXPECT_EQ(occurrences(dxf.str(), "\nLWPOLYLINE\n"), 1u);  // the frame
}

// A stencil for both faces: the underside's pieces get a group and a layer of their own.
TEST(Stencil, TheUndersidesPiecesGetTheirOwnGroupAndLayer) {
  const Box2 frame{Vec2::Zero(), Vec2(0.2, 0.1)};
  const auto left = stencil_outline(
      *make_polygon({{0.01, 0.01}, {0.09, 0.01}, {0.09, 0.09}, {0.01, 0.09}}), frame);
  const auto right = stencil_outline(
      *make_polygon({{0.11, 0.01}, {0.19, 0.01}, {0.19, 0.09}, {0.11, 0.09}}), frame);
  std::ostringstream svg, dxf, plain;
  write_svg(svg, left, frame, right);
  write_svg(plain, left, frame);
  EXPECT_NE(svg.str().find("id=\"resin_bottom\""), std::string::npos);
  EXPECT_EQ(plain.str().find("resin_bottom"), std::string::npos);
  EXPECT_NE(svg.str().find("<polygon points=\"10.0000,90.0000 90.0000,90.0000 90.0000,10.0000 "
                           "10.0000,10.0000\"/>"),
            std::string::npos);  // y flipped about the frame
  write_dxf(dxf, left, frame, right);
  EXPECT_NE(dxf.str().find("\nRESIN_BOTTOM\n"), std::string::npos);
  EXPECT_NE(dxf.str().find("\nRESIN\n"), std::string::npos);
}

}  // namespace
}  // namespace membra
