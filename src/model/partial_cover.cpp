#include "membra/model/partial_cover.hpp"

namespace membra {

int triangles_across(const Sheet& sheet, const Points& x, const Pattern& pattern, double margin) {
  constexpr int n = 6;  // barycentric points at sixths: corners, edges and inside
  int count = 0;
  for (const Triangle& t : sheet.triangles) {
    const Vec2 a = x.col(t[0]).head<2>(), b = x.col(t[1]).head<2>(), c = x.col(t[2]).head<2>();
    bool inside = false, outside = false;
    for (int i = 0; i <= n && !(inside && outside); ++i)
      for (int j = 0; i + j <= n && !(inside && outside); ++j) {
        const Vec2 p = (i * a + j * b + (n - i - j) * c) / n;
        const double f = pattern.field(p);
        inside = inside || f < -margin;
        outside = outside || f > margin;
      }
    count += inside && outside;
  }
  return count;
}

}  // namespace membra
