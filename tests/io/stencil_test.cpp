// The stencil: outlines traced from patterns, written as SVG and DXF at true scale.
#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "membra/io/stencil.hpp"

namespace membra {
namespace {

// A capsule strip, and an elliptical plate with a round hole; areas known exactly (m^2).
PatternPtr test_pattern(double& area) {
  const double mm = 1e-3;
  const auto strip = make_strip({{20 * mm, 150 * mm}, {120 * mm, 150 * mm}}, 10 * mm);
  const auto plate = make_difference({make_ellipse({150 * mm, 60 * mm}, 40 * mm, 25 * mm, 0.3),
                                      make_ellipse({150 * mm, 60 * mm}, 10 * mm, 10 * mm, 0.0)});
  area = (100 * 10 + std::numbers::pi * 25) * mm * mm +
         (std::numbers::pi * 40 * 25 - std::numbers::pi * 100) * mm * mm;
  return make_union({strip, plate});
}

// Area enclosed by an SVG path of M/L/Z commands, in the SVG's units (mm). SVG's y points down,
// which reverses orientation: counter-clockwise resin outlines come out with negative area.
double svg_area(const std::string& svg) {
  // (std::regex recurses per character and overflows the stack on long paths.)
  const size_t start = svg.find(" d=\"") + 4;
  const size_t end = svg.find('"', start);
  EXPECT_NE(end, std::string::npos);
  std::istringstream in(svg.substr(start, end - start));
  std::string tok;
  std::vector<std::pair<double, double>> loop;
  double total = 0.0;
  auto close = [&] {
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
      total += 0.5 * (loop[j].first * loop[i].second - loop[i].first * loop[j].second);
    loop.clear();
  };
  while (in >> tok) {
    if (tok == "Z") {
      close();
      continue;
    }
    const double x = std::stod(tok.substr(1));
    double y;
    in >> y;
    loop.emplace_back(x, y);
  }
  return -total;
}

TEST(Stencil, TracedOutlinesEncloseThePatternsArea) {
  double area = 0.0;
  const PatternPtr p = test_pattern(area);
  const Box2 frame{Vec2::Zero(), Vec2(0.3, 0.2)};
  const auto loops = trace_outlines(*p, frame, 0.25e-3);
  ASSERT_EQ(loops.size(), 3u);  // strip, plate, hole
  double traced = 0.0;
  int holes = 0;
  for (const auto& l : loops) {
    traced += signed_area(l);
    holes += signed_area(l) < 0.0;
  }
  EXPECT_EQ(holes, 1);
  EXPECT_NEAR(traced / area, 1.0, 1e-3);

  std::ostringstream svg;
  write_svg(svg, loops, frame);
  EXPECT_NE(svg.str().find("width=\"300.0000mm\""), std::string::npos);
  EXPECT_NEAR(svg_area(svg.str()) / (area * 1e6), 1.0, 1e-3);  // parsed back, in mm^2

  std::ostringstream dxf;
  write_dxf(dxf, loops, frame);
  const std::string d = dxf.str();
  size_t polylines = 0;
  for (size_t at = d.find("POLYLINE"); at != std::string::npos; at = d.find("POLYLINE", at + 1))
    ++polylines;
  EXPECT_EQ(polylines, 4u);                                  // the frame and three outlines
  EXPECT_NE(d.find("$INSUNITS\n70\n4"), std::string::npos);  // millimetres
}

// A stencil for both faces: the underside's pieces get a path and a layer of their own.
TEST(Stencil, TheUndersidesPiecesGetTheirOwnPathAndLayer) {
  const Box2 frame{Vec2::Zero(), Vec2(0.2, 0.1)};
  const auto left = trace_outlines(
      *make_polygon({{0.01, 0.01}, {0.09, 0.01}, {0.09, 0.09}, {0.01, 0.09}}), frame, 0.25e-3);
  const auto right = trace_outlines(
      *make_polygon({{0.11, 0.01}, {0.19, 0.01}, {0.19, 0.09}, {0.11, 0.09}}), frame, 0.25e-3);
  std::ostringstream svg, dxf, plain;
  write_svg(svg, left, frame, right);
  write_svg(plain, left, frame);
  EXPECT_NE(svg.str().find("id=\"resin_bottom\""), std::string::npos);
  EXPECT_EQ(plain.str().find("resin_bottom"), std::string::npos);
  EXPECT_NEAR(svg_area(svg.str()), 80.0 * 80.0, 1.0);  // the first path: the top's, mm^2
  write_dxf(dxf, left, frame, right);
  EXPECT_NE(dxf.str().find("\nRESIN_BOTTOM\n"), std::string::npos);
  EXPECT_NE(dxf.str().find("\nRESIN\n"), std::string::npos);
}

TEST(Stencil, PatternsAreClippedToTheFrame) {
  // A strip running off the right edge: only the part on the frame is resin.
  const auto strip = make_strip({{0.1, 0.1}, {0.5, 0.1}}, 0.01);
  const auto loops = trace_outlines(*strip, {Vec2::Zero(), Vec2(0.3, 0.2)}, 0.25e-3);
  ASSERT_EQ(loops.size(), 1u);
  const double expected =
      0.2 * 0.01 + std::numbers::pi * 0.005 * 0.005 / 2.0;  // half a cap at x = 0.1
  EXPECT_NEAR(signed_area(loops[0]) / expected, 1.0, 1e-3);
}

}  // namespace
}  // namespace membra
