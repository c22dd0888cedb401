// The stencil's outline from the pattern's own geometry: exact loops for polygons and ellipses,
// booleans as the pieces that bound the whole, areas against closed forms.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/model/pattern_stencil.hpp"

namespace membra {
namespace {

constexpr double kPi = std::numbers::pi;
const Box2 kStencilFrame{Vec2::Zero(), Vec2(0.3, 0.2)};

double total_area(const std::vector<CurveLoop>& loops) {
  double a = 0.0;
  for (const auto& l : loops) a += loop_area(l);
  return a;
}

bool closed(const CurveLoop& l) {
  for (size_t i = 0; i < l.size(); ++i)
    if ((l[i].end() - l[(i + 1) % l.size()].start()).norm() > 1e-7) return false;
  return true;
}

TEST(PatternStencil, AnEllipseIsOneArcAndAPolygonItsCorners) {
  const auto loops = stencil_outline(
      *make_union({make_ellipse({0.1, 0.1}, 0.05, 0.03, 0.4),
                   make_polygon({{0.2, 0.05}, {0.25, 0.05}, {0.25, 0.1}, {0.2, 0.1}})}),
      kStencilFrame);
  ASSERT_EQ(loops.size(), 2u);
  int ellipses = 0, squares = 0;
  for (const auto& l : loops) {
    ellipses += l.size() == 1 && l[0].full_ellipse();
    squares += l.size() == 4;
    EXPECT_GT(loop_area(l), 0.0);  // counter-clockwise: resin on the left
  }
  EXPECT_EQ(ellipses, 1);
  EXPECT_EQ(squares, 1);
  EXPECT_NEAR(total_area(loops), kPi * 0.05 * 0.03 + 0.05 * 0.05, 1e-15);
}

TEST(PatternStencil, OverlappingDiscsUniteAlongTheirArcs) {
  // Two discs of radius r, centres d apart: the union is 2 pi r^2 less the lens.
  const double r = 0.04, d = 0.05;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
  const auto loops = stencil_outline(
      *make_union({make_ellipse({0.1, 0.1}, r, r, 0.0), make_ellipse({0.1 + d, 0.1}, r, r, 0.0)}),
      kStencilFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 2u);  // two arcs, no segments
  EXPECT_TRUE(closed(loops[0]));
  EXPECT_NEAR(loop_area(loops[0]), 2 * kPi * r * r - lens, 1e-12);
}

TEST(PatternStencil, ADifferenceCutsAHoleOrABite) {
  // A square with a round hole, and a square bitten by a disc centred on its corner.
  const auto square = make_polygon({{0.05, 0.05}, {0.15, 0.05}, {0.15, 0.15}, {0.05, 0.15}});
  const auto holed = stencil_outline(
      *make_difference({square, make_ellipse({0.1, 0.1}, 0.02, 0.02, 0.0)}), kStencilFrame);
  ASSERT_EQ(holed.size(), 2u);
  EXPECT_NEAR(total_area(holed), 0.01 - kPi * 4e-4, 1e-15);
  EXPECT_TRUE(loop_area(holed[0]) < 0.0 || loop_area(holed[1]) < 0.0);  // the hole, clockwise
  const auto bitten = stencil_outline(
      *make_difference({square, make_ellipse({0.15, 0.15}, 0.03, 0.03, 0.0)}), kStencilFrame);
  ASSERT_EQ(bitten.size(), 1u);
  EXPECT_TRUE(closed(bitten[0]));
  EXPECT_NEAR(loop_area(bitten[0]), 0.01 - 0.25 * kPi * 9e-4, 1e-13);
}

TEST(PatternStencil, TheFrameClipsWhatReachesPastIt) {
  // A disc centred on the frame's left edge: half of it, one arc and one segment.
  const auto loops = stencil_outline(*make_ellipse({0.0, 0.1}, 0.03, 0.03, 0.0), kStencilFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 2u);
  EXPECT_NEAR(loop_area(loops[0]), 0.5 * kPi * 9e-4, 1e-13);
}

TEST(PatternStencil, AbuttingSquaresMergeAlongTheEdgeTheyShare) {
  const auto loops = stencil_outline(
      *make_union({make_polygon({{0.05, 0.05}, {0.1, 0.05}, {0.1, 0.1}, {0.05, 0.1}}),
                   make_polygon({{0.1, 0.07}, {0.15, 0.07}, {0.15, 0.12}, {0.1, 0.12}})}),
      kStencilFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(closed(loops[0]));
  EXPECT_NEAR(loop_area(loops[0]), 2 * 0.05 * 0.05, 1e-15);
}

TEST(PatternStencil, PrimitivesWithoutAnExactFormAreTracedToTheTolerance) {
  // A capsule strip (rectangle and two half discs) crossing an exact ellipse.
  const double mm = 1e-3;
  const auto strip = make_strip({{20 * mm, 100 * mm}, {120 * mm, 100 * mm}}, 10 * mm);
  const auto loops = stencil_outline(*strip, kStencilFrame);
  ASSERT_EQ(loops.size(), 1u);
  const double capsule = (100 * 10 + kPi * 25) * mm * mm;
  EXPECT_NEAR(loop_area(loops[0]) / capsule, 1.0, 1e-3);
  const auto crossed = stencil_outline(
      *make_union({strip, make_ellipse({0.12, 0.1}, 0.02, 0.02, 0.0)}), kStencilFrame);
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_TRUE(closed(crossed[0]));
  // The capsule's end cap lies inside the disc; the strip reaches it at x = 0.12 - x_in, and
  // the sliver between that line and the disc's arc is the disc's already.
  const double w = 5 * mm, R = 0.02, x_in = std::sqrt(R * R - w * w);
  const double sliver = R * R * std::asin(w / R) - w * x_in;
  const double expected = kPi * R * R + 2 * w * (0.1 - x_in) + 0.5 * kPi * w * w - sliver;
  EXPECT_NEAR(total_area(crossed) / expected, 1.0, 1e-3);
}

}  // namespace
}  // namespace membra
