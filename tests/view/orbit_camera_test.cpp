// The camera's matrices and its rays agree, and orbit, pan and zoom move it as a user expects.
#include <gtest/gtest.h>

#include "membra/geometry/orbit_camera.hpp"

namespace membra {
namespace {

Eigen::Vector2d to_pixel(const OrbitCamera& c, const Vec3& p, int w, int h) {
  const Eigen::Vector4d clip = c.view_projection(static_cast<double>(w) / h) * p.homogeneous();
  return {(clip.x() + 1.0) * 0.5 * w, (1.0 - clip.y()) * 0.5 * h};
}

TEST(OrbitCamera, TargetProjectsToTheCentreAndTheCentreRayHitsIt) {
  OrbitCamera c;
  c.fit(Vec3(1.0, 2.0, 3.0), 0.5);
  const Eigen::Vector2d px = to_pixel(c, c.target, 800, 600);
  EXPECT_NEAR(px.x(), 400.0, 1e-9);
  EXPECT_NEAR(px.y(), 300.0, 1e-9);
  const Ray r = c.ray(400, 300, 800, 600);
  // The ray passes through the target: its distance from the line is zero.
  EXPECT_NEAR((c.target - r.origin).cross(r.direction).norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.direction.norm(), 1.0, 1e-12);
}

TEST(OrbitCamera, RaysGoThroughThePixelTheyAreCastFrom) {
  OrbitCamera c;
  c.azimuth = 30;
  c.elevation = 50;
  c.fit(Vec3::Zero(), 2.0);
  for (const auto& [px, py] : {std::pair{10.0, 20.0}, std::pair{700.0, 580.0}}) {
    const Ray r = c.ray(px, py, 800, 600);
    const Vec3 p = r.origin + 1.7 * r.direction;  // any point along it
    const Eigen::Vector2d back = to_pixel(c, p, 800, 600);
    EXPECT_NEAR(back.x(), px, 1e-9);
    EXPECT_NEAR(back.y(), py, 1e-9);
  }
}

TEST(OrbitCamera, OrbitPanZoom) {
  OrbitCamera c;
  c.fit(Vec3::Zero(), 1.0, 1.0);
  c.orbit(10.0, 100.0);
  EXPECT_DOUBLE_EQ(c.elevation, 90.0);  // clamped: straight down, never over the top
  EXPECT_DOUBLE_EQ(c.azimuth, -50.0);
  c.zoom(2.0);
  EXPECT_DOUBLE_EQ(c.half_height, 0.5);
  // Dragging right by the viewport's height moves the view left by its visible height.
  const Vec3 right = c.rotation().row(0).transpose();
  c.pan(600.0, 0.0, 600);
  EXPECT_NEAR((c.target + 1.0 * right).norm(), 0.0, 1e-12);
  // Looking down the z-axis the basis stays orthonormal.
  const Eigen::Matrix3d r = c.rotation();
  EXPECT_NEAR((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace membra
