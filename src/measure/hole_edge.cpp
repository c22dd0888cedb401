#include "membra/measure/hole_edge.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include <Eigen/Dense>

namespace membra {

std::optional<double> sample_field(const GridSheet& g, const std::vector<double>& field,
                                   const Vec2& p) {
  const double u = p.x() / g.hx(), v = p.y() / g.hy();
  const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
  if (i < 0 || j < 0 || i + 1 >= g.nx() || j + 1 >= g.ny()) return std::nullopt;
  const int q[4] = {g.particle(i, j), g.particle(i + 1, j), g.particle(i, j + 1),
                    g.particle(i + 1, j + 1)};
  for (int k : q)
    if (k < 0) return std::nullopt;
  const double a = u - i, b = v - j;
  return (1 - a) * (1 - b) * field[q[0]] + a * (1 - b) * field[q[1]] + (1 - a) * b * field[q[2]] +
         a * b * field[q[3]];
}

std::optional<double> edge_value(const GridSheet& g, const std::vector<double>& field,
                                 const Vec2& centre, double radius, const Vec2& direction) {
  const double h = std::max(g.hx(), g.hy());
  constexpr int kFirst = 3, kLast = 8;  // spacings off the circle: past the staircase's reach
  Eigen::Matrix<double, kLast - kFirst + 1, 3> a;
  Eigen::Matrix<double, kLast - kFirst + 1, 1> y;
  for (int d = kFirst; d <= kLast; ++d) {
    const double r = radius + d * h;
    const auto s = sample_field(g, field, centre + r * direction);
    if (!s) return std::nullopt;
    const double u = radius * radius / (r * r);
    a.row(d - kFirst) << 1.0, u, u * u;
    y(d - kFirst) = *s;
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(y);
  return c.sum();  // at u = 1
}

HoleEdge hole_edge(const GridSheet& g, const std::vector<double>& field,
                   const std::vector<Vec2>& removed, int rays) {
  HoleEdge e;
  if (removed.empty() || rays <= 0) return e;
  // The hole's area: every cell with a removed corner went with it.
  std::set<std::pair<int, int>> cells;
  for (const Vec2& p : removed) {
    e.centre += p;
    const int i = static_cast<int>(std::lround(p.x() / g.hx())),
              j = static_cast<int>(std::lround(p.y() / g.hy()));
    for (int di = -1; di <= 0; ++di)
      for (int dj = -1; dj <= 0; ++dj)
        if (i + di >= 0 && j + dj >= 0 && i + di + 1 < g.nx() && j + dj + 1 < g.ny())
          cells.insert({i + di, j + dj});
  }
  e.centre /= static_cast<double>(removed.size());
  e.radius = std::sqrt(static_cast<double>(cells.size()) * g.hx() * g.hy() / std::numbers::pi);
  // A hole of a few spacings has no smooth field to read: the samples would reach several
  // radii out, where the quadratic in R^2/r^2 no longer carries the edge.
  if (e.radius < kMinHoleRadius * std::max(g.hx(), g.hy())) return e;
  for (int k = 0; k < rays; ++k) {
    const double t = 2.0 * std::numbers::pi * k / rays;
    const auto v = edge_value(g, field, e.centre, e.radius, Vec2(std::cos(t), std::sin(t)));
    if (!v) continue;
    if (!e.valid || *v > e.value) {
      e.value = *v;
      e.angle = t;
      e.valid = true;
    }
  }
  return e;
}

}  // namespace membra
