#pragma once
// Curves of the plane as a stencil draws them: a straight segment or an arc of an ellipse, each
// parametrized by s in [0, 1], and the points where two of them cross (docs/outputs.md, "The
// stencil").
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

struct PlaneCurve {
  bool arc = false;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();  // a segment's ends
  // An arc: c + R(angle) (rx cos t, ry sin t) for t from t0 to t1 (t1 < t0 runs clockwise).
  Vec2 centre = Vec2::Zero();
  double rx = 0.0, ry = 0.0, angle = 0.0, t0 = 0.0, t1 = 0.0;

  static PlaneCurve segment(Vec2 from, Vec2 to);
  static PlaneCurve ellipse_arc(Vec2 centre, double rx, double ry, double angle, double t0,
                                double t1);

  Vec2 at(double s) const;
  Vec2 tangent(double s) const;  // d at / ds, not normalized
  Vec2 start() const { return at(0.0); }
  Vec2 end() const { return at(1.0); }
  // The part from s0 to s1 (s1 < s0 reverses it).
  PlaneCurve piece(double s0, double s1) const;
  PlaneCurve reversed() const { return piece(1.0, 0.0); }
  bool full_ellipse() const;  // an arc that closes on itself
  // Twice the signed area it sweeps about the origin: integral of x dy - y dx.
  double sweep_area2() const;
};

// The parameters (s on a, s on b) where the two curves cross or touch, and where collinear
// segments overlap, the ends of each inside the other. Ellipse against ellipse is found by
// sampling (720 samples a turn) and bisection: two crossings closer than a sample may be missed.
std::vector<std::pair<double, double>> intersections(const PlaneCurve& a, const PlaneCurve& b);

// A box around the curve (the whole ellipse's for an arc).
void curve_bounds(const PlaneCurve& c, Vec2& lo, Vec2& hi);

}  // namespace membra
