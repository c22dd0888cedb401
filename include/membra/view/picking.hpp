#pragma once
// What the mouse points at: the first triangle a ray hits (Moller-Trumbore), the hit point and
// the nearest particle of that triangle.
#include <optional>
#include <vector>

#include "membra/geometry/orbit_camera.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

struct PickHit {
  int triangle = -1;
  Vec3 point = Vec3::Zero();  // where the ray meets the surface
  int particle = -1;          // the triangle's corner nearest to the point
  double distance = 0.0;      // along the ray from its origin
};

// The nearest hit in front of the ray's origin, or nullopt when the ray misses the mesh.
std::optional<PickHit> pick(const Ray& ray, const Points& x,
                            const std::vector<Triangle>& triangles);

}  // namespace membra
