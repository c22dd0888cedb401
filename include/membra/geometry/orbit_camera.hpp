#pragma once
// An orthographic camera that orbits a target point: the viewer's 3-D view and the CLI's
// renders use the same matrices, and picking casts rays through them. Pure math, no OpenGL.
#include <Eigen/Core>

#include "membra/core/vec.hpp"

namespace membra {

// A ray from `origin` along the unit vector `direction`.
struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = -Vec3::UnitZ();
};

struct OrbitCamera {
  Vec3 target = Vec3::Zero();  // the point the camera looks at
  double azimuth = -60.0;      // degrees around +z from +x
  double elevation = 35.0;     // degrees above the xy-plane, within [-90, 90]
  double half_height = 1.0;    // half the visible height at the target (same unit as target)
  double depth = 1.0;          // half the depth range kept (clipping), same unit

  // Looks at a bounding sphere so that it fills 1/margin of the view's shorter side.
  void fit(const Vec3& centre, double radius, double margin = 1.1);
  // Turns by the given angles (degrees); the elevation stays within [-90, 90].
  void orbit(double d_azimuth, double d_elevation);
  // Moves the target by a drag of (dx, dy) pixels in a viewport of the given height.
  void pan(double dx, double dy, int viewport_height);
  // Zooms in by `factor` (> 1 in, < 1 out).
  void zoom(double factor);

  // Rows: right, up, and back (towards the viewer), in world coordinates.
  Eigen::Matrix3d rotation() const;
  // World to clip space for a viewport of the given aspect (width / height).
  Eigen::Matrix4d view_projection(double aspect) const;
  // The ray through pixel (px, py) (origin top-left) of a width x height viewport.
  Ray ray(double px, double py, int width, int height) const;
};

}  // namespace membra
