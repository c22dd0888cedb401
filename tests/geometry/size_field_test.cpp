#include "membra/geometry/size_field.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace membra {
namespace {

// A 10 mm strip across a 100 mm square (the square's edges are boundaries too).
std::vector<Polyline2> strip_in_square() {
  const Polyline2 square = {{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}};
  const Polyline2 strip = {{0, 0.045}, {0.1, 0.045}, {0.1, 0.055}, {0, 0.055}};
  return {square, strip};
}

TEST(SizeField, AsksForElementsAcrossTheNarrowestPieceAndGrowsAwayFromIt) {
  const SizeFieldOptions o{0.02, 4, 0.3};
  const SizeField h(strip_in_square(), Vec2::Zero(), Vec2(0.1, 0.1), o);
  // The strip is 10 mm wide, the gaps on either side 45 mm.
  EXPECT_NEAR(h.narrowest().width, 0.010, 1e-12);
  EXPECT_NEAR(h.smallest(), 0.0025, 0.0025 * 0.05);
  EXPECT_NEAR(h(Vec2(0.05, 0.045)), 0.0025, 0.0025 * 0.05);  // 4 elements across the strip
  // In its middle, 5 mm from both sides: 2.5 mm + 0.3 x 5 mm.
  EXPECT_NEAR(h(Vec2(0.05, 0.05)), 0.004, 0.004 * 0.05);
  // 20 mm away from the strip: 2.5 mm + 0.3 x 20 mm, within the chamfer sweeps' 8 %.
  EXPECT_NEAR(h(Vec2(0.05, 0.075)), 0.0085, 0.0085 * 0.08);
  // Never above max_edge, never below the finest size.
  for (double x = 0.0; x <= 0.1; x += 0.005)
    for (double y = 0.0; y <= 0.1; y += 0.005) {
      EXPECT_LE(h(Vec2(x, y)), o.max_edge + 1e-15);
      EXPECT_GE(h(Vec2(x, y)), h.smallest() - 1e-15);
    }
}

// The narrowest feature that is narrow along a length: the strip (10 mm), and not the 0.5 mm
// pinch where a square's corner nearly touches another square's side.
TEST(NarrowestFeature, IsTheStripNotAPinchPoint) {
  const NarrowestFeature strip = narrowest_feature(strip_in_square(), 0.001, 0.01);
  EXPECT_NEAR(strip.width, 0.010, 1e-12);
  EXPECT_NEAR(strip.at.y(), 0.045, 0.0101);  // on the strip's boundary
  const Polyline2 square = {{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}};
  const Polyline2 a = {{0.02, 0.02}, {0.04, 0.02}, {0.04, 0.04}, {0.02, 0.04}};
  // b's corner 0.5 mm from a's right side, tilted 45 degrees so only the corner comes close.
  const double c = 0.0405, m = 0.05;
  const Polyline2 b = {
      {c, 0.03}, {c + m / 2, 0.03 - m / 2}, {c + m, 0.03}, {c + m / 2, 0.03 + m / 2}};
  const NarrowestFeature pinch = narrowest_feature({square, a, b}, 0.0005, 0.01);
  EXPECT_GT(pinch.width, 5 * 0.0005);
  // Without the length asked, the pinch is what it finds.
  EXPECT_LT(narrowest_feature({square, a, b}, 0.0005, 0.0).width, 0.001);
  EXPECT_THROW(narrowest_feature({square}, 0.0, 0.01), std::invalid_argument);
}

TEST(SizeField, IsLipschitzAtTheGradingRate) {
  const SizeFieldOptions o{0.02, 4, 0.3};
  const SizeField h(strip_in_square(), Vec2::Zero(), Vec2(0.1, 0.1), o);
  const double d = 0.001;
  for (double y = 0.0; y + d <= 0.1; y += d)
    EXPECT_LE(std::abs(h(Vec2(0.05, y + d)) - h(Vec2(0.05, y))), o.grading * d * 1.5 + 1e-12);
}

TEST(SizeField, CountsTheTrianglesItWouldMake) {
  // A unit square, one element across it asked: max_edge everywhere, 4 / (sqrt 3 h^2) per unit
  // area.
  const SizeField h({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, Vec2::Zero(), Vec2(1, 1), {0.5, 1, 0.3});
  EXPECT_NEAR(h.expected_triangles(), 4.0 / (std::sqrt(3.0) * 0.25), 1e-9);
}

TEST(SizeField, RefusesBadSettings) {
  const auto b = strip_in_square();
  EXPECT_THROW(SizeField(b, Vec2::Zero(), Vec2(0.1, 0.1), {0.0, 4, 0.3}), std::invalid_argument);
  EXPECT_THROW(SizeField(b, Vec2::Zero(), Vec2(0.1, 0.1), {0.01, 0, 0.3}), std::invalid_argument);
  EXPECT_THROW(SizeField(b, Vec2::Zero(), Vec2(0.1, 0.1), {0.01, 4, 0.0}), std::invalid_argument);
  EXPECT_THROW(SizeField(b, Vec2::Zero(), Vec2(0.0, 0.1), {0.01, 4, 0.3}), std::invalid_argument);
}

}  // namespace
}  // namespace membra
