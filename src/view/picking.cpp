#include "membra/view/picking.hpp"

#include <cmath>
#include <limits>

namespace membra {

std::optional<PickHit> pick(const Ray& ray, const Points& x,
                            const std::vector<Triangle>& triangles) {
  std::optional<PickHit> best;
  double best_t = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    const Vec3 a = x.col(t[0]), e1 = x.col(t[1]) - a, e2 = x.col(t[2]) - a;
    const Vec3 p = ray.direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;  // the ray runs along the triangle's plane
    const Vec3 s = ray.origin - a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 q = s.cross(e1);
    const double v = ray.direction.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double dist = e2.dot(q) / det;
    if (dist < 0.0 || dist >= best_t) continue;
    best_t = dist;
    PickHit h;
    h.triangle = static_cast<int>(i);
    h.point = ray.origin + dist * ray.direction;
    h.distance = dist;
    const double w[3] = {1.0 - u - v, u, v};  // barycentric weights of the corners
    int k = 0;
    for (int c = 1; c < 3; ++c)
      if (w[c] > w[k]) k = c;
    h.particle = t[k];
    best = h;
  }
  return best;
}

}  // namespace membra
