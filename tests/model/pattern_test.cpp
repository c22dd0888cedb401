// Pattern primitives and their composition.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/model/pattern.hpp"

namespace membra {
namespace {

TEST(Pattern, StripIsTheSetWithinHalfAWidthOfThePolyline) {
  const auto s = make_strip({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}, 0.2);
  EXPECT_TRUE(s->contains({0.5, 0.09}));
  EXPECT_FALSE(s->contains({0.5, 0.11}));
  EXPECT_TRUE(s->contains({1.09, 0.5}));
  EXPECT_TRUE(s->contains({-0.09, 0.0}));  // round cap
  EXPECT_FALSE(s->contains({0.5, 0.5}));
  EXPECT_THROW(make_strip({{0, 0}, {1, 0}}, 0.0), std::invalid_argument);
}

TEST(Pattern, EllipseAndRing) {
  const auto e = make_ellipse({1.0, 1.0}, 0.5, 0.25, 0.0);
  EXPECT_TRUE(e->contains({1.49, 1.0}));
  EXPECT_FALSE(e->contains({1.0, 1.26}));
  const auto rotated = make_ellipse({0.0, 0.0}, 0.5, 0.25, std::numbers::pi / 2);
  EXPECT_TRUE(rotated->contains({0.0, 0.49}));
  EXPECT_FALSE(rotated->contains({0.49, 0.0}));
  const auto ring = make_ellipse_ring({0.0, 0.0}, 0.5, 0.5, 0.0, 0.1);
  EXPECT_TRUE(ring->contains({0.54, 0.0}));
  EXPECT_FALSE(ring->contains({0.0, 0.0}));
  EXPECT_FALSE(ring->contains({0.56, 0.0}));
}

TEST(Pattern, HyperbolaBranchesOpenAlongTheirAxis) {
  // x^2 - y^2 = 1: passes through (1, 0) and (sqrt(2), 1).
  const auto h = make_hyperbola({0.0, 0.0}, 1.0, 1.0, 0.0, 0.05, true, 5.0);
  EXPECT_TRUE(h->contains({1.0, 0.0}));
  EXPECT_TRUE(h->contains({-std::sqrt(2.0), -1.0}));
  EXPECT_FALSE(h->contains({0.0, 1.0}));
  EXPECT_FALSE(h->contains({0.0, 0.0}));
  const auto v = make_hyperbola({0.0, 0.0}, 1.0, 1.0, 0.0, 0.05, false, 5.0);
  EXPECT_TRUE(v->contains({0.0, 1.0}));
  EXPECT_FALSE(v->contains({1.0, 0.0}));
}

TEST(Pattern, PolygonUnionDifference) {
  const auto square = make_polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const auto hole = make_ellipse({0.5, 0.5}, 0.2, 0.2, 0.0);
  const auto frame = make_difference({square, hole});
  EXPECT_TRUE(frame->contains({0.1, 0.1}));
  EXPECT_FALSE(frame->contains({0.5, 0.5}));
  const auto both = make_union({hole, make_polygon({{2, 2}, {3, 2}, {2, 3}})});
  EXPECT_TRUE(both->contains({0.5, 0.5}));
  EXPECT_TRUE(both->contains({2.2, 2.2}));
  EXPECT_FALSE(both->contains({2.9, 2.9}));
  EXPECT_NEAR(both->bounds().max.x(), 3.0, 1e-15);
}

TEST(Pattern, RasterDarkIsResinRowZeroOnTop) {
  // 2 x 2 image: top-left black, others white, placed on [0, 2] x [0, 2].
  const auto r = make_raster({0.0f, 1.0f, 1.0f, 1.0f}, 2, 2, {0, 0}, {2, 2}, 0.5, false);
  EXPECT_TRUE(r->contains({0.5, 1.5}));
  EXPECT_FALSE(r->contains({0.5, 0.5}));
  EXPECT_FALSE(r->contains({1.5, 1.5}));
  const auto inv = make_raster({0.0f, 1.0f, 1.0f, 1.0f}, 2, 2, {0, 0}, {2, 2}, 0.5, true);
  EXPECT_FALSE(inv->contains({0.5, 1.5}));
}

TEST(Pattern, FractionOfASegmentInside) {
  const auto half = make_polygon({{0, -1}, {0.5, -1}, {0.5, 1}, {0, 1}});
  EXPECT_NEAR(fraction_inside(*half, {0, 0}, {1, 0}), 0.5, 1e-12);
  EXPECT_NEAR(fraction_inside(*half, {0.1, 0}, {0.4, 0}), 1.0, 1e-12);
  EXPECT_NEAR(fraction_inside(*half, {0.6, 0}, {1, 0}), 0.0, 1e-12);
}

}  // namespace
}  // namespace membra
