// Segments and elliptical arcs: points, swept areas and crossings against closed forms.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/geometry/plane_curve.hpp"

namespace membra {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PlaneCurve, AWholeEllipseSweepsItsArea) {
  const auto e = PlaneCurve::ellipse_arc({0.3, -0.2}, 0.05, 0.02, 0.7, 0.0, 2.0 * kPi);
  EXPECT_TRUE(e.full_ellipse());
  EXPECT_NEAR(0.5 * e.sweep_area2(), kPi * 0.05 * 0.02, 1e-15);
  EXPECT_NEAR((e.start() - e.end()).norm(), 0.0, 1e-15);
  // Clockwise, the area is negative; a half turn plus its chord is half the ellipse.
  EXPECT_NEAR(0.5 * e.reversed().sweep_area2(), -kPi * 0.05 * 0.02, 1e-15);
  const PlaneCurve half = e.piece(0.0, 0.5);
  const double chord = PlaneCurve::segment(half.end(), half.start()).sweep_area2();
  EXPECT_NEAR(0.5 * (half.sweep_area2() + chord), 0.5 * kPi * 0.05 * 0.02, 1e-15);
}

TEST(PlaneCurve, SegmentsCrossWhereTheLinesMeet) {
  const auto a = PlaneCurve::segment({0, 0}, {2, 2}), b = PlaneCurve::segment({0, 2}, {2, 0});
  const auto hits = intersections(a, b);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].first, 0.5, 1e-15);
  EXPECT_NEAR(hits[0].second, 0.5, 1e-15);
  EXPECT_TRUE(intersections(a, PlaneCurve::segment({3, 0}, {4, 1})).empty());
  // Collinear overlap: each one's ends inside the other split it.
  const auto c = PlaneCurve::segment({1, 1}, {3, 3});
  const auto overlap = intersections(a, c);
  ASSERT_EQ(overlap.size(), 2u);
  EXPECT_NEAR(overlap[0].first, 0.5, 1e-15);   // c's start on a
  EXPECT_NEAR(overlap[1].second, 0.5, 1e-15);  // a's end on c
}

TEST(PlaneCurve, ALineMeetsAnEllipseAtTheRootsOfItsQuadratic) {
  // x^2/4 + y^2 = 1 and y = 0.5: x = +-sqrt(3).
  const auto e = PlaneCurve::ellipse_arc({0, 0}, 2.0, 1.0, 0.0, 0.0, 2.0 * kPi);
  const auto line = PlaneCurve::segment({-3, 0.5}, {3, 0.5});
  const auto hits = intersections(line, e);
  ASSERT_EQ(hits.size(), 2u);
  for (const auto& [s, u] : hits) {
    EXPECT_NEAR(std::abs(line.at(s).x()), std::sqrt(3.0), 1e-12);
    EXPECT_NEAR((e.at(u) - line.at(s)).norm(), 0.0, 1e-12);
  }
  // The upper half arc only: both points are on it; the lower half: none.
  EXPECT_EQ(intersections(line, e.piece(0.0, 0.5)).size(), 2u);
  EXPECT_TRUE(intersections(e.piece(0.5, 1.0), line).empty());
}

TEST(PlaneCurve, TwoCirclesCrossOnTheirRadicalLine) {
  // Unit circles at (0, 0) and (1, 0) cross at (1/2, +-sqrt(3)/2).
  const auto a = PlaneCurve::ellipse_arc({0, 0}, 1.0, 1.0, 0.0, 0.0, 2.0 * kPi);
  const auto b = PlaneCurve::ellipse_arc({1, 0}, 1.0, 1.0, 0.3, 0.0, 2.0 * kPi);
  const auto hits = intersections(a, b);
  ASSERT_EQ(hits.size(), 2u);
  for (const auto& [s, u] : hits) {
    EXPECT_NEAR(a.at(s).x(), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(a.at(s).y()), std::sqrt(3.0) / 2.0, 1e-12);
    EXPECT_NEAR((b.at(u) - a.at(s)).norm(), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace membra
