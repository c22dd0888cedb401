#include "membra/model/mesh_outlines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "membra/model/pattern_stencil.hpp"

namespace membra {
namespace {

// How far the curve's point halfway between s0 and s1 lies from the chord between them.
double sagitta(const PlaneCurve& c, double s0, double s1) {
  const Vec2 a = c.at(s0), b = c.at(s1), m = c.at(0.5 * (s0 + s1));
  const Vec2 e = b - a;
  const double l = e.norm();
  if (!(l > 0.0)) return (m - a).norm();
  return std::abs(e.x() * (m - a).y() - e.y() * (m - a).x()) / l;
}

}  // namespace

std::vector<Vec2> sample_curve(const PlaneCurve& curve, double tolerance) {
  if (!curve.arc) return {curve.a};
  // Eight pieces a turn to start with, so that no bisection test sees a chord of half an ellipse
  // whose middle happens to lie near it; then each piece halved until its chord is close enough
  // (at most 2^16 pieces: a tolerance far below the arc's size stops there).
  const double turns = std::abs(curve.t1 - curve.t0) / (2.0 * std::numbers::pi);
  const int start = std::max(1, static_cast<int>(std::ceil(8.0 * turns)));
  std::vector<Vec2> out;
  std::vector<std::pair<double, double>> stack;
  for (int k = start - 1; k >= 0; --k)
    stack.push_back({static_cast<double>(k) / start, static_cast<double>(k + 1) / start});
  while (!stack.empty()) {
    const auto [s0, s1] = stack.back();
    stack.pop_back();
    if (s1 - s0 > 1.0 / 65536 && sagitta(curve, s0, s1) > tolerance) {
      const double mid = 0.5 * (s0 + s1);
      stack.push_back({mid, s1});
      stack.push_back({s0, mid});
      continue;
    }
    out.push_back(curve.at(s0));
  }
  return out;
}

std::vector<Polygon2> mesh_outlines(const Pattern& pattern, const Box2& frame,
                                    const BoundaryOptions& options) {
  std::vector<Polygon2> out;
  for (const CurveLoop& loop : stencil_outline(pattern, frame, options)) {
    if (loop.empty() || (loop.back().end() - loop.front().start()).norm() > 1e-7)
      return pattern_boundaries(pattern, frame, options);
    Polygon2 poly;
    // Ends that two curves computed a hair apart are one vertex, not an edge the mesher must
    // resolve.
    const double merge = 1e-3 * options.tolerance;
    for (const PlaneCurve& c : loop)
      for (const Vec2& p : sample_curve(c, options.tolerance))
        if (poly.empty() || (p - poly.back()).norm() > merge) poly.push_back(p);
    while (poly.size() > 1 && (poly.back() - poly.front()).norm() <= merge) poly.pop_back();
    // A polygon finer than the tolerance (a CAD outline of 10^5 vertices) keeps only the
    // vertices that matter: each kept one is one of its own, the rest within the tolerance.
    poly = simplify_closed(poly, options.tolerance);
    if (poly.size() >= 3 && std::abs(signed_area(poly)) > 0.0) out.push_back(std::move(poly));
  }
  return out;
}

}  // namespace membra
