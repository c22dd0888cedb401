#include "membra/model/partial_cover.hpp"

#include <cmath>
#include <limits>

namespace membra {
namespace {

// The pattern's field at p as a distance (m). A field that is not one (an image's grey level
// times its pixel, an ellipse's algebraic form) is divided by the length of its gradient, taken
// by central differences h apart; where it is flat (inside an image's dark plateau) the point is
// as far inside or outside as it gets.
double distance_at(const Pattern& pattern, const Vec2& p, double h) {
  const double f = pattern.field(p);
  if (pattern.field_is_distance()) return f;
  const double gx = pattern.field(p + Vec2(h, 0.0)) - pattern.field(p - Vec2(h, 0.0));
  const double gy = pattern.field(p + Vec2(0.0, h)) - pattern.field(p - Vec2(0.0, h));
  const double g = std::hypot(gx, gy) / (2.0 * h);
  if (g > 0.0) return f / g;
  return f == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), f);
}

}  // namespace

int triangles_across(const Sheet& sheet, const Points& x, const Pattern& pattern, double margin) {
  constexpr int n = 6;  // barycentric points at sixths: corners, edges and inside
  const auto count_of = static_cast<long>(sheet.triangles.size());
  int count = 0;
  // Each triangle's answer is its own: the sum is the same for any thread count.
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long k = 0; k < count_of; ++k) {
    const Triangle& t = sheet.triangles[static_cast<size_t>(k)];
    const Vec2 a = x.col(t[0]).head<2>(), b = x.col(t[1]).head<2>(), c = x.col(t[2]).head<2>();
    bool inside = false, outside = false;
    for (int i = 0; i <= n && !(inside && outside); ++i)
      for (int j = 0; i + j <= n && !(inside && outside); ++j) {
        const double d = distance_at(pattern, (i * a + j * b + (n - i - j) * c) / n, margin);
        inside = inside || d < -margin;
        outside = outside || d > margin;
      }
    count += inside && outside;
  }
  return count;
}

}  // namespace membra
