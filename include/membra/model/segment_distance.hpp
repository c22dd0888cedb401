#pragma once
// Squared distance from a point to a segment, shared by the strip pattern and the polygon's
// edge grid; the distance to an open polyline, by the continuum's slits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

// The point of segment a-b nearest p (a for a segment of zero length).
inline Vec2 nearest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

inline double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  return (nearest_on_segment(p, a, b) - p).squaredNorm();
}

// Distance from p to the open polyline `line` (infinity for fewer than two points).
inline double polyline_distance(const Vec2& p, const std::vector<Vec2>& line) {
  double d2 = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < line.size(); ++k)
    d2 = std::min(d2, segment_distance2(p, line[k], line[k + 1]));
  return std::sqrt(d2);
}

}  // namespace membra
