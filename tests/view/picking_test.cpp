// Picking finds the first surface under the mouse, in the 3-D and the 2-D view.
#include <gtest/gtest.h>

#include "membra/view/flat_view.hpp"
#include "membra/view/picking.hpp"

namespace membra {
namespace {

// Two unit squares (two triangles each), at z = 0 and z = 1.
struct TwoLayers {
  Points x{3, 8};
  std::vector<Triangle> t;
  TwoLayers() {
    for (int layer = 0; layer < 2; ++layer) {
      const int o = 4 * layer;
      x.col(o + 0) = Vec3(0, 0, layer);
      x.col(o + 1) = Vec3(1, 0, layer);
      x.col(o + 2) = Vec3(1, 1, layer);
      x.col(o + 3) = Vec3(0, 1, layer);
      t.push_back({o + 0, o + 1, o + 2});
      t.push_back({o + 0, o + 2, o + 3});
    }
  }
};

TEST(Picking, TheNearestSurfaceAlongTheRayWins) {
  const TwoLayers m;
  const auto hit = pick({Vec3(0.2, 0.7, 5.0), -Vec3::UnitZ()}, m.x, m.t);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.z(), 1.0, 1e-12);  // the upper layer
  EXPECT_NEAR(hit->point.x(), 0.2, 1e-12);
  EXPECT_NEAR(hit->point.y(), 0.7, 1e-12);
  EXPECT_NEAR(hit->distance, 4.0, 1e-12);
  EXPECT_EQ(hit->particle, 7);  // (0, 1) is the nearest corner
  // From below, the lower layer.
  const auto below = pick({Vec3(0.2, 0.7, -5.0), Vec3::UnitZ()}, m.x, m.t);
  ASSERT_TRUE(below);
  EXPECT_NEAR(below->point.z(), 0.0, 1e-12);
}

TEST(Picking, MissesAndRaysPointingAwayFindNothing) {
  const TwoLayers m;
  EXPECT_FALSE(pick({Vec3(2.0, 0.5, 5.0), -Vec3::UnitZ()}, m.x, m.t));
  EXPECT_FALSE(pick({Vec3(0.5, 0.5, 5.0), Vec3::UnitZ()}, m.x, m.t));
}

TEST(FlatView, PixelsAndFrameCoordinatesRoundTripAndMatchTheMatrix) {
  FlatView f;
  f.box = {Vec2(0, 0), Vec2(0.3, 0.2)};
  f.width = 800;
  f.height = 600;
  const Vec2 p(0.25, 0.05);
  const Eigen::Vector2d px = f.to_pixel(p);
  const Vec2 back = f.to_frame(px.x(), px.y());
  EXPECT_NEAR((back - p).norm(), 0.0, 1e-12);
  // The whole box fits inside the margin, with equal scale along x and y.
  const Eigen::Vector2d lo = f.to_pixel(f.box.min), hi = f.to_pixel(f.box.max);
  EXPECT_GE(lo.x(), f.margin - 1e-9);
  EXPECT_LE(hi.x(), f.width - f.margin + 1e-9);
  EXPECT_NEAR(hi.x() - lo.x(), 0.3 * f.scale(), 1e-9);
  EXPECT_NEAR(lo.y() - hi.y(), 0.2 * f.scale(), 1e-9);
  const Eigen::Vector4d clip = f.view_projection() * Eigen::Vector4d(p.x(), p.y(), 0.7, 1.0);
  EXPECT_NEAR((clip.x() + 1) * 0.5 * f.width, px.x(), 1e-9);
  EXPECT_NEAR((1 - clip.y()) * 0.5 * f.height, px.y(), 1e-9);
}

}  // namespace
}  // namespace membra
