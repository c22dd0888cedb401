#include "membra/model/mesh_outlines.hpp"
#include "membra/model/segment_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace membra {
namespace mesh_outlines_test {
namespace {

const Box2 kFrame{Vec2(0, 0), Vec2(0.3, 0.2)};

// A circle as a 60-gon: edges of 1 mm, too short for the tracing's corner restoration, so the
// traced outline loses the polygon's own vertices.
std::vector<Vec2> fine_polygon(const Vec2& c, double r, int n) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n + 0.01;
    v.push_back(c + r * Vec2(std::cos(t), std::sin(t)));
  }
  return v;
}

double nearest(const Polygon2& loop, const Vec2& q) {
  double d = 1.0;
  for (const Vec2& p : loop) d = std::min(d, (p - q).norm());
  return d;
}

TEST(MeshOutlines, APolygonWithShortEdgesComesOutWithItsOwnVertices) {
  const std::vector<Vec2> poly = fine_polygon({0.15, 0.1}, 0.0095, 60);
  const auto loops = mesh_outlines(*make_polygon(poly), kFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), poly.size());
  for (const Vec2& corner : poly) EXPECT_EQ(nearest(loops[0], corner), 0.0);
  EXPECT_GT(signed_area(loops[0]), 0.0);  // resin on the left
}

// A CAD outline of 10^5 vertices (2.5 um apart) keeps the few that matter, each one of its own,
// the dropped ones within the tolerance of the kept chords: the mesh is not forced to microns.
TEST(MeshOutlines, AVeryFinePolygonKeepsOnlyTheVerticesThatMatter) {
  const std::vector<Vec2> poly = fine_polygon({0.15, 0.1}, 0.04, 100000);
  BoundaryOptions o;
  o.tolerance = 2e-5;
  const auto loops = mesh_outlines(*make_polygon(poly), kFrame, o);
  ASSERT_EQ(loops.size(), 1u);
  // A circle of 40 mm in chords of sagitta <= 20 um: pi / acos(1 - 20 um / 40 mm) = 99 at least.
  EXPECT_GT(loops[0].size(), 99u);
  EXPECT_LT(loops[0].size(), 400u);
  for (const Vec2& p : loops[0]) EXPECT_EQ(nearest(poly, p), 0.0);
  std::vector<Vec2> closed = loops[0];
  closed.push_back(closed.front());
  for (size_t k = 0; k < poly.size(); k += 97)  // every dropped vertex near a kept chord
    EXPECT_LE(polyline_distance(poly[k], closed), o.tolerance);
}

TEST(MeshOutlines, AnEllipseIsSampledOnItsOutlineWithinTheChordTolerance) {
  BoundaryOptions o;
  o.tolerance = 2e-5;
  const Vec2 c(0.15, 0.1);
  const double a = 0.08, b = 0.05, angle = 0.3;
  const auto loops = mesh_outlines(*make_ellipse(c, a, b, angle), kFrame, o);
  ASSERT_EQ(loops.size(), 1u);
  const Polygon2& loop = loops[0];
  const double cs = std::cos(angle), sn = std::sin(angle);
  // (u/a)^2 + (v/b)^2 - 1 in the ellipse's frame, and the distance it says: the level over its
  // gradient's length (first order, exact enough at the sagittas' 20 um against radii of 31 mm
  // and more).
  const auto level = [&](const Vec2& p) {
    const Vec2 d = p - c;
    const double u = cs * d.x() + sn * d.y(), v = -sn * d.x() + cs * d.y();
    return u * u / (a * a) + v * v / (b * b) - 1.0;
  };
  const auto distance = [&](const Vec2& p) {
    const Vec2 d = p - c;
    const double u = cs * d.x() + sn * d.y(), v = -sn * d.x() + cs * d.y();
    return level(p) / (2.0 * std::hypot(u / (a * a), v / (b * b)));
  };
  double worst_chord = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) {
    EXPECT_NEAR(level(loop[k]), 0.0, 1e-12);
    // A chord's midpoint lies inside the ellipse by about its sagitta.
    const Vec2 mid = 0.5 * (loop[k] + loop[(k + 1) % loop.size()]);
    worst_chord = std::max(worst_chord, -distance(mid));
  }
  EXPECT_LT(worst_chord, 1.01 * o.tolerance);
  EXPECT_GT(worst_chord, 0.25 * o.tolerance);  // not sampled far finer than asked
  const double area = std::numbers::pi * a * b;
  EXPECT_NEAR(signed_area(loop), area, area * 1e-3);
}

TEST(MeshOutlines, AUnionKeepsBothPartsCornersAndTheirCrossings) {
  // A square over the ellipse's right end: the outline runs along the ellipse, then the square.
  const std::vector<Vec2> square = {{0.2, 0.08}, {0.26, 0.08}, {0.26, 0.12}, {0.2, 0.12}};
  const PatternPtr both =
      make_union({make_ellipse({0.15, 0.1}, 0.08, 0.05, 0.0), make_polygon(square)});
  const auto loops = mesh_outlines(*both, kFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(nearest(loops[0], square[1]), 0.0);  // the corners outside the ellipse
  EXPECT_EQ(nearest(loops[0], square[2]), 0.0);
  // Where the square's top edge leaves the ellipse: x = 0.15 + 0.08 sqrt(1 - 0.4^2).
  EXPECT_LT(nearest(loops[0], {0.15 + 0.08 * std::sqrt(1.0 - 0.16), 0.12}), 1e-12);
  EXPECT_GT(nearest(loops[0], square[0]), 1e-3);  // inside the ellipse: not on the outline
}

TEST(MeshOutlines, APatternThatLeavesTheFrameClosesAlongItsEdge) {
  const std::vector<Vec2> band = {{-0.05, 0.09}, {0.35, 0.09}, {0.35, 0.11}, {-0.05, 0.11}};
  const auto loops = mesh_outlines(*make_polygon(band), kFrame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 4u);
  EXPECT_NEAR(std::abs(signed_area(loops[0])), 0.3 * 0.02, 1e-15);
  for (const Vec2& p : loops[0]) EXPECT_NEAR(std::min(p.x(), 0.3 - p.x()), 0.0, 1e-15);
}

TEST(MeshOutlines, AStripHasNoExactOutlineAndIsTraced) {
  const PatternPtr strip = make_strip({{0.05, 0.1}, {0.25, 0.1}}, 0.01);
  const auto loops = mesh_outlines(*strip, kFrame);
  ASSERT_EQ(loops.size(), 1u);
  // A stadium: 0.2 x 0.01 plus a disk of radius 5 mm, within the chords' shortfall.
  const double area = 0.2 * 0.01 + std::numbers::pi * 0.005 * 0.005;
  EXPECT_NEAR(std::abs(signed_area(loops[0])), area, area * 2e-3);
}

}  // namespace
}  // namespace mesh_outlines_test
}  // namespace membra
