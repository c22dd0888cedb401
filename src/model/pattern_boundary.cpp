#include "membra/model/pattern_boundary.hpp"

#include <algorithm>
#include <cmath>

#include "membra/model/segment_distance.hpp"

namespace membra {
namespace {

// Marks the vertices of the open chain [first, last] that Douglas-Peucker keeps.
void keep_chain(const Polygon2& poly, size_t first, size_t last, double tolerance,
                std::vector<bool>& keep) {
  const size_t n = poly.size();
  std::vector<std::pair<size_t, size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = 0.0;
    size_t at = a;
    for (size_t k = (a + 1) % n; k != b; k = (k + 1) % n) {
      const double d = std::sqrt(segment_distance2(poly[k], poly[a], poly[b]));
      if (d > worst) worst = d, at = k;
    }
    if (worst <= tolerance) continue;
    keep[at] = true;
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
}

// The field traced: the pattern's, clipped to the frame (positive outside it).
double clipped_field(const Pattern& pattern, const Box2& frame, const Vec2& p) {
  const double box = std::max(
      {frame.min.x() - p.x(), p.x() - frame.max.x(), frame.min.y() - p.y(), p.y() - frame.max.y()});
  return std::max(pattern.field(p), box);
}

// A few Newton steps along the field's gradient onto its zero level; the point stays where it
// was when the gradient vanishes or the step would leave the cell it was traced in.
Vec2 project(const Pattern& pattern, const Box2& frame, Vec2 p, double step) {
  const double h = 1e-3 * step;
  const Vec2 start = p;
  for (int it = 0; it < 4; ++it) {
    const double f = clipped_field(pattern, frame, p);
    const Vec2 grad((clipped_field(pattern, frame, p + Vec2(h, 0)) -
                     clipped_field(pattern, frame, p - Vec2(h, 0))) /
                        (2 * h),
                    (clipped_field(pattern, frame, p + Vec2(0, h)) -
                     clipped_field(pattern, frame, p - Vec2(0, h))) /
                        (2 * h));
    const double g2 = grad.squaredNorm();
    if (!(g2 > 1e-12)) break;
    const Vec2 next = p - (f / g2) * grad;
    if ((next - start).norm() > step) break;
    p = next;
  }
  return p;
}

// Where the lines through (a, b) and (c, d) meet, if they are not near parallel.
bool meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Vec2& x) {
  const Vec2 u = b - a, v = d - c;
  const double den = u.x() * v.y() - u.y() * v.x();
  if (std::abs(den) < 1e-3 * u.norm() * v.norm()) return false;
  const Vec2 w = c - a;
  x = a + ((w.x() * v.y() - w.y() * v.x()) / den) * u;
  return true;
}

// The tracing cuts a corner as a run of short edges between two long straight ones: the run is
// replaced by the point where the long edges meet, when that point lies on the outline.
Polygon2 restore_corners(const Pattern& pattern, const Box2& frame, Polygon2 poly,
                         const BoundaryOptions& o) {
  const double short_edge = 2.5 * o.step, long_edge = 2.0 * short_edge;
  auto len = [&](size_t k) { return (poly[(k + 1) % poly.size()] - poly[k]).norm(); };
  for (size_t i = 0; poly.size() > 4 && i < poly.size(); ++i) {
    const size_t n = poly.size();
    if (len((i + n - 1) % n) < long_edge || len(i) > short_edge) continue;
    size_t j = i, run = 0;  // the run of short edges i -> j
    double run_length = 0.0;
    while (len(j % n) <= short_edge && run < 4) run_length += len(j % n), j = (j + 1) % n, ++run;
    if (run == 4 || run_length > 3.0 * short_edge || len(j) < long_edge) continue;
    const Vec2 &a = poly[(i + n - 1) % n], &b = poly[i], &c = poly[j], &d = poly[(j + 1) % n];
    Vec2 x;
    if (!meet(a, b, d, c, x) || (x - b).norm() > long_edge || (x - c).norm() > long_edge) continue;
    if (std::abs(clipped_field(pattern, frame, x)) > o.tolerance) continue;
    Polygon2 out;  // the polygon with the run i..j replaced by x
    for (size_t k = 0; k < n; ++k) {
      const bool in_run = j > i ? (k >= i && k <= j) : (k >= i || k <= j);
      if (k == i)
        out.push_back(x);
      else if (!in_run)
        out.push_back(poly[k]);
    }
    poly = std::move(out);
  }
  return poly;
}

}  // namespace

Polygon2 simplify_closed(const Polygon2& poly, double tolerance) {
  const size_t n = poly.size();
  if (n <= 3) return poly;
  size_t far = 0;  // the vertex farthest from the first splits the loop into two chains
  for (size_t k = 1; k < n; ++k)
    if ((poly[k] - poly[0]).squaredNorm() > (poly[far] - poly[0]).squaredNorm()) far = k;
  std::vector<bool> keep(n, false);
  keep[0] = keep[far] = true;
  keep_chain(poly, 0, far, tolerance, keep);
  keep_chain(poly, far, 0, tolerance, keep);
  Polygon2 out;
  for (size_t k = 0; k < n; ++k)
    if (keep[k]) out.push_back(poly[k]);
  return out;
}

std::vector<Polygon2> pattern_boundaries(const Pattern& pattern, const Box2& frame,
                                         const BoundaryOptions& o) {
  std::vector<Polygon2> out;
  for (Polygon2 loop : trace_outlines(pattern, frame, o.step)) {
    for (Vec2& p : loop) p = project(pattern, frame, p, o.step);
    Polygon2 simple = restore_corners(pattern, frame, simplify_closed(loop, o.tolerance), o);
    if (simple.size() >= 3 && std::abs(signed_area(simple)) > 0.0) out.push_back(std::move(simple));
  }
  return out;
}

}  // namespace membra
