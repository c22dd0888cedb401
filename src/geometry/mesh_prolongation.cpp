#include "membra/geometry/mesh_prolongation.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>
#include <tuple>

#include "membra/geometry/triangle_locator.hpp"

namespace membra {
namespace {

// p's barycentric weights in the plane triangle (a, b, c); all >= 0 inside.
Vec3 weights_in(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  if (det == 0.0) return Vec3::Constant(-std::numeric_limits<double>::infinity());
  const double wb = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / det;
  const double wc = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / det;
  return Vec3(1.0 - wb - wc, wb, wc);
}

// The coarse triangle for a fine vertex at p, probed at q (p nudged into one of its own fine
// triangles): among the triangles holding p, the one q lies deepest in (so a slit's lips each
// find their side; interpolation at p is then exact for a linear field); where none holds p,
// the one p lies least outside of. -1 if every candidate is degenerate.
int coarse_triangle(const Vec2& p, const Vec2& q, const Eigen::Matrix2Xd& xy,
                    const std::vector<Triangle>& triangles, std::span<const int> candidates) {
  std::tuple<bool, double, int> best{false, -std::numeric_limits<double>::infinity(), -1};
  for (int t : candidates) {
    const Triangle& tri = triangles[static_cast<size_t>(t)];
    const double at_p = weights_in(p, xy.col(tri[0]), xy.col(tri[1]), xy.col(tri[2])).minCoeff();
    const double at_q = weights_in(q, xy.col(tri[0]), xy.col(tri[1]), xy.col(tri[2])).minCoeff();
    const bool holds = at_p >= -1e-9;
    const std::tuple<bool, double, int> key{holds, holds ? at_q : at_p, t};
    if (std::get<0>(key) > std::get<0>(best) ||
        (std::get<0>(key) == std::get<0>(best) && std::get<1>(key) > std::get<1>(best)))
      best = key;
  }
  return std::get<2>(best);
}

}  // namespace

Points prolongate_on_mesh(const Points& coarse_reference,
                          const std::vector<Triangle>& coarse_triangles, const Points& coarse_x,
                          const Points& fine_reference,
                          const std::vector<Triangle>& fine_triangles) {
  if (coarse_triangles.empty())
    throw std::invalid_argument("prolongate_on_mesh: the coarse mesh has no triangle");
  const Eigen::Matrix2Xd xy = coarse_reference.topRows<2>();
  const TriangleLocator locator(xy, coarse_triangles);
  Points out(3, fine_reference.cols());
  std::vector<int> every(coarse_triangles.size());
  for (size_t t = 0; t < every.size(); ++t) every[t] = static_cast<int>(t);
  // Where each fine vertex looks for its coarse triangle: a thousandth of the way from its point
  // towards the centroid of one of its own triangles (its lip's side on a slit).
  Eigen::Matrix2Xd probe = fine_reference.topRows<2>();
  std::vector<bool> placed(static_cast<size_t>(fine_reference.cols()), false);
  for (const Triangle& t : fine_triangles) {
    const Vec2 centroid = (fine_reference.col(t[0]).head<2>() + fine_reference.col(t[1]).head<2>() +
                           fine_reference.col(t[2]).head<2>()) /
                          3.0;
    for (int k = 0; k < 3; ++k)
      if (!placed[static_cast<size_t>(t[k])]) {
        probe.col(t[k]) += 1e-3 * (centroid - probe.col(t[k]));
        placed[static_cast<size_t>(t[k])] = true;
      }
  }
  for (Eigen::Index v = 0; v < fine_reference.cols(); ++v) {
    const Vec2 p = fine_reference.col(v).head<2>(), q = probe.col(v);
    int t = coarse_triangle(p, q, xy, coarse_triangles, locator.candidates(q));
    if (t < 0 || weights_in(p, xy.col(coarse_triangles[static_cast<size_t>(t)][0]),
                            xy.col(coarse_triangles[static_cast<size_t>(t)][1]),
                            xy.col(coarse_triangles[static_cast<size_t>(t)][2]))
                         .minCoeff() < -1e-9)
      t = coarse_triangle(p, q, xy, coarse_triangles, every);  // outside: rare, so scan all
    if (t < 0)
      throw std::invalid_argument("prolongate_on_mesh: every coarse triangle is degenerate");
    const Triangle& tri = coarse_triangles[static_cast<size_t>(t)];
    Vec3 w = weights_in(p, xy.col(tri[0]), xy.col(tri[1]), xy.col(tri[2])).cwiseMax(0.0);
    w /= w.sum();
    out.col(v) =
        w[0] * coarse_x.col(tri[0]) + w[1] * coarse_x.col(tri[1]) + w[2] * coarse_x.col(tri[2]);
  }
  return out;
}

}  // namespace membra
