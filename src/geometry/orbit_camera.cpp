#include "membra/geometry/orbit_camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace membra {

void OrbitCamera::fit(const Vec3& centre, double radius, double margin) {
  target = centre;
  radius = std::max(radius, 1e-12);
  half_height = radius * margin;
  depth = 4.0 * radius;  // generous: panning and zooming must not clip the sheet
}

void OrbitCamera::orbit(double d_azimuth, double d_elevation) {
  azimuth = std::remainder(azimuth + d_azimuth, 360.0);
  elevation = std::clamp(elevation + d_elevation, -90.0, 90.0);
}

void OrbitCamera::pan(double dx, double dy, int viewport_height) {
  const double per_pixel = 2.0 * half_height / std::max(1, viewport_height);
  const Eigen::Matrix3d r = rotation();
  target += per_pixel * (-dx * r.row(0).transpose() + dy * r.row(1).transpose());
}

void OrbitCamera::zoom(double factor) {
  if (factor > 0.0 && std::isfinite(factor)) half_height /= factor;
}

Eigen::Matrix3d OrbitCamera::rotation() const {
  const double az = azimuth * std::numbers::pi / 180, el = elevation * std::numbers::pi / 180;
  const Vec3 back(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  // Looking straight down or up, "right" follows the azimuth instead of the (degenerate) z-axis.
  Vec3 right = (-back).cross(Vec3::UnitZ());
  if (right.norm() < 1e-9) right = Vec3(-std::sin(az), std::cos(az), 0.0);
  right.normalize();
  const Vec3 up = back.cross(right);
  Eigen::Matrix3d r;
  r.row(0) = right;
  r.row(1) = up;
  r.row(2) = back;
  return r;
}

Eigen::Matrix4d OrbitCamera::view_projection(double aspect) const {
  const Eigen::Matrix3d r = rotation();
  const Eigen::Vector3d scale(1.0 / (half_height * aspect), 1.0 / half_height, -1.0 / depth);
  const Eigen::Matrix3d s = scale.asDiagonal() * r;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = s;
  m.topRightCorner<3, 1>() = -(s * target);
  return m;
}

Ray OrbitCamera::ray(double px, double py, int width, int height) const {
  const Eigen::Matrix3d r = rotation();
  const double aspect = static_cast<double>(width) / std::max(1, height);
  const double u = (2.0 * px / std::max(1, width) - 1.0) * half_height * aspect;
  const double v = (1.0 - 2.0 * py / std::max(1, height)) * half_height;
  Ray ray;
  ray.direction = -r.row(2).transpose();
  ray.origin =
      target + u * r.row(0).transpose() + v * r.row(1).transpose() + depth * r.row(2).transpose();
  return ray;
}

}  // namespace membra
