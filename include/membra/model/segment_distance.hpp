#pragma once
// Squared distance from a point to a segment, shared by the strip pattern and the polygon's
// edge grid.
#include <algorithm>

#include "membra/core/vec.hpp"

namespace membra {

inline double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

}  // namespace membra
