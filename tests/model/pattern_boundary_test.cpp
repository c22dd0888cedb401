#include "membra/model/pattern_boundary.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace membra {
namespace {

const Box2 kFrame{Vec2(0, 0), Vec2(0.3, 0.2)};

TEST(PatternBoundary, APolygonComesOutAsGivenCornersIncluded) {
  // Corners off the tracing grid (0.25 mm) on purpose.
  const std::vector<Vec2> square = {
      {0.1003, 0.0511}, {0.1157, 0.0511}, {0.1157, 0.0667}, {0.1003, 0.0667}};
  const auto loops = pattern_boundaries(*make_polygon(square), kFrame);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 4u);
  for (const Vec2& corner : square) {
    double nearest = 1.0;
    for (const Vec2& p : loops[0]) nearest = std::min(nearest, (p - corner).norm());
    EXPECT_LT(nearest, 1e-9);
  }
}

// A strip across a frame whose top edge is off the tracing grid, its side exactly on a grid line
// (the field zero at samples): the side comes out straight, its corners at the frame's edge.
// (Two crossings at one sample once made a zero-length edge that dropped the corner: the side
// ran slanted by a cell, 0.25 mm over 163 mm, and exp2's strips read 7.67 mm wide for 8.)
TEST(PatternBoundary, AStripSideOnTheGridMeetsTheFrameAtItsCorner) {
  const Box2 frame{Vec2(0, 0), Vec2(0.3, 0.1633)};
  const auto loops = pattern_boundaries(*make_strip({{0.030, 0.0}, {0.030, 0.200}}, 0.012), frame);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 4u);
  for (const Vec2& corner :
       {Vec2(0.024, 0.0), Vec2(0.036, 0.0), Vec2(0.036, 0.1633), Vec2(0.024, 0.1633)}) {
    double nearest = 1.0;
    for (const Vec2& p : loops[0]) nearest = std::min(nearest, (p - corner).norm());
    EXPECT_LT(nearest, 1e-9);
  }
}

TEST(PatternBoundary, AnEllipseComesOutAsChordsWithinTheTolerance) {
  const BoundaryOptions o;  // 0.02 mm chords
  const auto loops = pattern_boundaries(*make_ellipse({0.15, 0.1}, 0.08, 0.05, 0.3), kFrame, o);
  ASSERT_EQ(loops.size(), 1u);
  const double exact = std::numbers::pi * 0.08 * 0.05;
  EXPECT_NEAR(signed_area(loops[0]), exact, exact * 1e-3);
  // Vertices on the ellipse, chord midpoints no farther than the tolerance from it.
  const double c = std::cos(0.3), s = std::sin(0.3);
  auto radius = [&](const Vec2& p) {
    const Vec2 d = p - Vec2(0.15, 0.1);
    const double u = c * d.x() + s * d.y(), v = -s * d.x() + c * d.y();
    return (std::hypot(u / 0.08, v / 0.05) - 1.0) * 0.05;  // ~ distance near the outline
  };
  for (size_t k = 0; k < loops[0].size(); ++k) {
    EXPECT_LT(std::abs(radius(loops[0][k])), 1e-7);
    const Vec2 mid = 0.5 * (loops[0][k] + loops[0][(k + 1) % loops[0].size()]);
    EXPECT_LT(std::abs(radius(mid)), 1.5 * o.tolerance);
  }
  // Far fewer vertices than the 0.25 mm trace: chords of about sqrt(8 r tol).
  EXPECT_LT(loops[0].size(), 400u);
}

TEST(PatternBoundary, APatternReachingTheFrameClosesAlongIt) {
  const auto loops = pattern_boundaries(*make_strip({{0.0, 0.1}, {0.3, 0.1}}, 0.012), kFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_NEAR(signed_area(loops[0]), 0.3 * 0.012, 0.3 * 0.012 * 1e-6);
  EXPECT_EQ(loops[0].size(), 4u);  // a rectangle: the strip's sides and the frame's edges
}

TEST(PatternBoundary, DouglasPeuckerKeepsWhatStraysMoreThanTheTolerance) {
  const Polygon2 p = {{0, 0}, {0.5, 1e-6}, {1, 0}, {1, 1}, {0.5, 1.1}, {0, 1}};
  EXPECT_EQ(simplify_closed(p, 1e-5).size(), 5u);  // the 1e-6 bump goes, the 0.1 one stays
}

}  // namespace
}  // namespace membra
