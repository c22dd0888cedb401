// Targets have the geometry they are asked for; shapes compare as distances after rigid motion;
// stencils keep their pieces and gaps at least the minimum feature wide.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "membra/design/shape_distance.hpp"
#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_correspondence.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {
namespace {

TEST(TargetSurface, CapHasTheSphericalCapsAreaAndHeight) {
  TargetSpec s;
  s.kind = "cap";
  s.size = 0.16;
  s.height = 0.024;
  s.resolution = 81;
  const TargetSurface t = make_target(s);
  const double radius = (0.08 * 0.08 + s.height * s.height) / (2 * s.height);
  // The grid clips the disk's rim to whole cells: within 3 % of 2 pi R h.
  EXPECT_NEAR(t.area, 2 * std::numbers::pi * radius * s.height, 0.03 * t.area);
  EXPECT_NEAR(t.x.row(2).maxCoeff(), s.height, 1e-4);
  EXPECT_NEAR(t.x.row(2).minCoeff(), 0.0, 1e-12);
  EXPECT_TRUE(t.disk);
  EXPECT_DOUBLE_EQ(t.diameter, 0.16);
}

TEST(TargetSurface, SaddleAndCylinder) {
  TargetSpec s;
  s.kind = "saddle";
  s.size = 0.15;
  s.height = 0.015;
  const TargetSurface saddle = make_target(s);
  EXPECT_NEAR(saddle.x.row(2).maxCoeff() - saddle.x.row(2).minCoeff(), 2 * s.height, 1e-12);
  s.kind = "cylinder";
  s.height = 0.02;
  const TargetSurface cyl = make_target(s);
  EXPECT_NEAR(cyl.x.row(2).maxCoeff(), s.height, 1e-12);
  // A cylinder is developable: its area is its unrolled width times its length.
  const double radius = (0.075 * 0.075 + s.height * s.height) / (2 * s.height);
  const double arc = 2 * radius * std::asin(0.075 / radius);
  EXPECT_NEAR(cyl.area, arc * 0.15, 1e-3 * cyl.area);
}

TEST(TargetSurface, BadTargetsAreRefused) {
  TargetSpec s;
  s.kind = "cap";
  s.size = 0.1;
  s.height = 0.06;  // more than the radius
  EXPECT_THROW(make_target(s), std::invalid_argument);
  s.kind = "height_field";
  s.formula = "x +* y";
  EXPECT_THROW(make_target(s), std::invalid_argument);
  s.kind = "torus";
  EXPECT_THROW(make_target(s), std::invalid_argument);
}

// An L-shaped OBJ target (a grid of 20 x 20 cells without its upper right quarter): heights
// looked up through the target's triangle locator are those a scan of every triangle gives, bit
// for bit, on the mesh, in the notch, outside it, on vertices and edges, and just off its rim.
TEST(TargetSurface, HeightsThroughTheLocatorAreTheScansHeights) {
  TargetSpec s;
  s.kind = "obj";
  const int n = 21;
  s.obj_x.resize(3, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.obj_x.col(j * n + i) = Vec3(0.005 * i, 0.005 * j, 0.01 * std::sin(0.3 * i + 0.2 * j));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (i >= 10 && j >= 10) continue;  // the notch
      const int a = j * n + i;
      s.obj_triangles.push_back({a, a + 1, a + n + 1});
      s.obj_triangles.push_back({a, a + n + 1, a + n});
    }
  const TargetSurface located = make_target(s);
  ASSERT_TRUE(located.locator);
  TargetSurface scanned = located;
  scanned.locator = nullptr;
  std::vector<Vec2> points;
  for (int j = -3; j <= 2 * n + 3; ++j)
    for (int i = -3; i <= 2 * n + 3; ++i)  // vertices, edge midpoints, cell centres, outside
      points.emplace_back(0.0025 * i - 0.05, 0.0025 * j - 0.05);
  for (const double off : {-1e-11, 1e-11, 1e-7})  // just inside and outside the rim
    for (int k = 0; k <= 10; ++k) points.emplace_back(0.05 + off, 0.01 * k - 0.05);
  points.emplace_back(std::nan(""), 0.0);
  for (const Vec2& p : points) {
    const double a = target_height(located, p), b = target_height(scanned, p);
    if (std::isnan(b))
      EXPECT_TRUE(std::isnan(a)) << p.transpose();
    else
      EXPECT_EQ(a, b) << p.transpose();
  }
}

TEST(ShapeDistance, AShapeMovedRigidlyIsAtDistanceZero) {
  TargetSpec s;
  s.kind = "saddle";
  s.size = 0.1;
  s.height = 0.01;
  s.resolution = 21;
  const TargetSurface t = make_target(s);
  // Turned over, turned by 100 degrees about z and shifted.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.5 * std::numbers::pi + 0.17, Vec3::UnitZ()) *
                            Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
  Points moved = (r * t.x).colwise() + Vec3(0.3, -0.1, 0.05);
  const ShapeError e = compare_shapes(moved, t.triangles, t);
  EXPECT_LT(e.rms, 1e-9);
  EXPECT_LT(e.max, 1e-8);
}

TEST(ShapeDistance, AFlatSheetIsAsFarFromACapAsItsSag) {
  TargetSpec s;
  s.kind = "cylinder";
  s.size = 0.1;
  s.height = 0.01;
  s.resolution = 31;
  const TargetSurface t = make_target(s);
  Points flat = t.x;
  flat.row(2).setZero();
  const ShapeError e = compare_shapes(flat, t.triangles, t);
  // The best plane lies within the sag: the error is a fraction of the rise, not zero.
  EXPECT_GT(e.rms, 0.15 * s.height);
  EXPECT_LT(e.rms, 0.6 * s.height);
}

TEST(MeshDistance, IsExactAboveATriangleAndBesideIt) {
  Points x(3, 3);
  x << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  const MeshDistance d(x, {{0, 1, 2}});
  EXPECT_NEAR(d.distance(Vec3(0.2, 0.2, 0.5)), 0.5, 1e-15);
  EXPECT_NEAR(d.distance(Vec3(2.0, 0.0, 0.0)), 1.0, 1e-15);             // beyond a corner
  EXPECT_NEAR(d.distance(Vec3(1.0, 1.0, 0.0)), std::sqrt(0.5), 1e-15);  // beside the long edge
}

TEST(StencilLayout, PiecesAndGapsAreNeverNarrowerThanTheMinimumFeature) {
  const Box2 frame{Vec2::Zero(), Vec2(0.2, 0.2)};
  StencilLayout l;
  l.cell = 0.02;
  l.min_feature = 0.004;
  EXPECT_TRUE(layout_stencil([](const Vec2&) { return 0.0; }, frame, l).pattern == nullptr);
  const Stencil full = layout_stencil([](const Vec2&) { return 1.0; }, frame, l);
  EXPECT_NEAR(full.resin_share, 1.0, 1e-12);
  EXPECT_EQ(full.pieces, 100);
  // A ramp of densities: each square's side is 0, the cell, or within [w, cell - w].
  const Stencil ramp = layout_stencil([](const Vec2& p) { return p.x() / 0.2; }, frame, l);
  ASSERT_EQ(ramp.spec.kind, PatternSpec::Kind::union_of);
  for (const PatternSpec& square : ramp.spec.parts) {
    const double side = square.points[1].x() - square.points[0].x();
    EXPECT_TRUE(std::abs(side - l.cell) < 1e-12 ||
                (side >= l.min_feature - 1e-12 && side <= l.cell - l.min_feature + 1e-12))
        << side;
  }
  EXPECT_NEAR(ramp.resin_share, 0.5, 0.1);
  // Inside an outline only.
  const Stencil disk =
      layout_stencil([](const Vec2&) { return 1.0; }, frame, l,
                     [](const Vec2& p) { return (p - Vec2(0.1, 0.1)).norm() < 0.1; });
  EXPECT_LT(disk.pieces, 100);
  EXPECT_GT(disk.pieces, 60);
  EXPECT_THROW(layout_stencil([](const Vec2&) { return 1.0; }, frame, {0.006, 0.004}),
               std::invalid_argument);
}

}  // namespace
}  // namespace membra
