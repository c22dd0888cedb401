#include "membra/geometry/plane_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace membra {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kSlack = 1e-12;  // parameters this far outside [0, 1] still count as on the curve

double cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

Vec2 rotate(const Vec2& q, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * q.x() - s * q.y(), s * q.x() + c * q.y()};
}

// The point in the arc's unit-circle coordinates: on the ellipse where its norm is 1.
Vec2 to_unit(const PlaneCurve& e, const Vec2& p) {
  const Vec2 q = rotate(p - e.centre, -e.angle);
  return {q.x() / e.rx, q.y() / e.ry};
}

// Where on the arc the point of unit-circle angle t lies, if it does.
std::optional<double> arc_param(const PlaneCurve& e, double t) {
  const double span = e.t1 - e.t0;
  if (std::abs(span) >= kTwoPi - kSlack) {
    double s = (t - e.t0) / span;
    s -= std::floor(s);
    return s;
  }
  for (int k = -2; k <= 2; ++k) {
    const double s = (t + k * kTwoPi - e.t0) / span;
    if (s >= -kSlack && s <= 1.0 + kSlack) return std::clamp(s, 0.0, 1.0);
  }
  return std::nullopt;
}

bool on_unit(double s) {
  return s >= -kSlack && s <= 1.0 + kSlack;
}

using Hits = std::vector<std::pair<double, double>>;

void segment_segment(const PlaneCurve& a, const PlaneCurve& b, Hits& hits) {
  const Vec2 d1 = a.b - a.a, d2 = b.b - b.a, w = b.a - a.a;
  const double denom = cross(d1, d2);
  if (std::abs(denom) > 1e-12 * d1.norm() * d2.norm()) {
    const double s = cross(w, d2) / denom, u = cross(w, d1) / denom;
    if (on_unit(s) && on_unit(u))
      hits.emplace_back(std::clamp(s, 0.0, 1.0), std::clamp(u, 0.0, 1.0));
    return;
  }
  // Parallel: where collinear, each segment's ends that fall inside the other split it.
  if (std::abs(cross(w, d1)) > 1e-12 * d1.norm() * std::max(d1.norm(), w.norm())) return;
  const auto along = [](const PlaneCurve& c, const Vec2& p) {
    const Vec2 d = c.b - c.a;
    return (p - c.a).dot(d) / d.squaredNorm();
  };
  for (double u : {0.0, 1.0})
    if (const double s = along(a, b.at(u)); s > kSlack && s < 1.0 - kSlack) hits.emplace_back(s, u);
  for (double s : {0.0, 1.0})
    if (const double u = along(b, a.at(s)); u > kSlack && u < 1.0 - kSlack) hits.emplace_back(s, u);
}

void segment_arc(const PlaneCurve& seg, const PlaneCurve& e, Hits& hits) {
  const Vec2 p = to_unit(e, seg.a), d = to_unit(e, seg.b) - p;
  const double qa = d.squaredNorm(), qb = 2.0 * p.dot(d), qc = p.squaredNorm() - 1.0;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (qa == 0.0 || disc < 0.0) return;
  const double root = std::sqrt(disc);
  for (double s : {(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)}) {
    if (!on_unit(s)) continue;
    const Vec2 q = p + s * d;
    if (const auto u = arc_param(e, std::atan2(q.y(), q.x())))
      hits.emplace_back(std::clamp(s, 0.0, 1.0), *u);
    if (root == 0.0) break;
  }
}

void arc_arc(const PlaneCurve& a, const PlaneCurve& b, Hits& hits) {
  const auto g = [&](double s) { return to_unit(b, a.at(s)).squaredNorm() - 1.0; };
  const int n = std::max(16, static_cast<int>(std::ceil(720.0 * std::abs(a.t1 - a.t0) / kTwoPi)));
  double s_prev = 0.0, g_prev = g(0.0);
  for (int i = 1; i <= n; ++i) {
    const double s = static_cast<double>(i) / n, gs = g(s);
    if (g_prev == 0.0 || (g_prev < 0.0) != (gs < 0.0)) {
      double lo = s_prev, hi = s, glo = g_prev;
      for (int k = 0; k < 60 && glo != 0.0; ++k) {
        const double mid = 0.5 * (lo + hi), gm = g(mid);
        if ((gm < 0.0) == (glo < 0.0))
          lo = mid, glo = gm;
        else
          hi = mid;
      }
      const double root = glo == 0.0 ? lo : 0.5 * (lo + hi);
      const Vec2 q = to_unit(b, a.at(root));
      if (const auto u = arc_param(b, std::atan2(q.y(), q.x()))) hits.emplace_back(root, *u);
    }
    s_prev = s, g_prev = gs;
  }
}

}  // namespace

PlaneCurve PlaneCurve::segment(Vec2 from, Vec2 to) {
  PlaneCurve c;
  c.a = from, c.b = to;
  return c;
}

PlaneCurve PlaneCurve::ellipse_arc(Vec2 centre, double rx, double ry, double angle, double t0,
                                   double t1) {
  PlaneCurve c;
  c.arc = true;
  c.centre = centre, c.rx = rx, c.ry = ry, c.angle = angle, c.t0 = t0, c.t1 = t1;
  return c;
}

Vec2 PlaneCurve::at(double s) const {
  if (!arc) return a + s * (b - a);
  const double t = t0 + s * (t1 - t0);
  return centre + rotate({rx * std::cos(t), ry * std::sin(t)}, angle);
}

Vec2 PlaneCurve::tangent(double s) const {
  if (!arc) return b - a;
  const double t = t0 + s * (t1 - t0);
  return (t1 - t0) * rotate({-rx * std::sin(t), ry * std::cos(t)}, angle);
}

PlaneCurve PlaneCurve::piece(double s0, double s1) const {
  if (!arc) return segment(at(s0), at(s1));
  const double span = t1 - t0;
  return ellipse_arc(centre, rx, ry, angle, t0 + s0 * span, t0 + s1 * span);
}

bool PlaneCurve::full_ellipse() const {
  return arc && std::abs(t1 - t0) >= kTwoPi - 1e-9;
}

double PlaneCurve::sweep_area2() const {
  if (!arc) return cross(a, b);
  const Vec2 q0 = at(0.0) - centre, q1 = at(1.0) - centre;
  return cross(centre, q1 - q0) + rx * ry * (t1 - t0);
}

std::vector<std::pair<double, double>> intersections(const PlaneCurve& a, const PlaneCurve& b) {
  Hits hits;
  if (!a.arc && !b.arc) {
    segment_segment(a, b, hits);
  } else if (!a.arc) {
    segment_arc(a, b, hits);
  } else if (!b.arc) {
    segment_arc(b, a, hits);
    for (auto& h : hits) std::swap(h.first, h.second);
  } else {
    arc_arc(a, b, hits);
  }
  return hits;
}

void curve_bounds(const PlaneCurve& c, Vec2& lo, Vec2& hi) {
  if (!c.arc) {
    lo = c.a.cwiseMin(c.b), hi = c.a.cwiseMax(c.b);
    return;
  }
  const double cs = std::cos(c.angle), sn = std::sin(c.angle);
  const Vec2 half(std::hypot(c.rx * cs, c.ry * sn), std::hypot(c.rx * sn, c.ry * cs));
  lo = c.centre - half, hi = c.centre + half;
}

}  // namespace membra
