// A hanging chain of stiff springs settles onto the catenary.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/solve/dynamics.hpp"

namespace membra {
namespace {

// Solves L = 2 a sinh(b / a) for the catenary parameter a by bisection.
double catenary_parameter(double length, double half_span) {
  double lo = 1e-3 * half_span, hi = 1e3 * half_span;  // f(a) = 2 a sinh(b/a) - L decreases in a
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (2.0 * mid * std::sinh(half_span / mid) > length ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(HangingChain, SagMatchesTheCatenaryWithinOnePercent) {
  const int segments = 40;
  const double length = 1.2, half_span = 0.5;  // m
  const double line_density = 0.1;             // kg/m
  const double seg = length / segments;
  const double m = line_density * seg;
  const double k = 1e4 / seg;  // EA = 1e4 N: strain ~ 1e-4

  // Start on a parabola of the right arc length (not the answer), equally spaced by arc length:
  // tabulate the parabola finely, then pick points at equal cumulative length.
  auto tabulate = [&](double sag, std::vector<Vec3>& pts, std::vector<double>& cum) {
    pts.clear();
    cum.clear();
    for (int i = 0; i <= 4000; ++i) {
      const double x = -half_span + 2.0 * half_span * i / 4000.0;
      pts.emplace_back(x, 0.0, -sag * (1.0 - (x / half_span) * (x / half_span)));
      cum.push_back(i == 0 ? 0.0 : cum.back() + (pts[i] - pts[i - 1]).norm());
    }
  };
  std::vector<Vec3> pts;
  std::vector<double> cum;
  double lo = 0.0, hi = length;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    tabulate(mid, pts, cum);
    (cum.back() < length ? lo : hi) = mid;
  }
  tabulate(lo, pts, cum);

  Model model;
  size_t seg_i = 0;
  for (int i = 0; i <= segments; ++i) {
    const double target = cum.back() * i / segments;
    while (seg_i + 2 < cum.size() && cum[seg_i + 1] < target) ++seg_i;
    const double t = (target - cum[seg_i]) / (cum[seg_i + 1] - cum[seg_i]);
    model.add_particle(m, pts[seg_i] + t * (pts[seg_i + 1] - pts[seg_i]));
  }
  model.pin(0);
  model.pin(segments);
  for (int i = 0; i < segments; ++i)
    model.springs.add(i, i + 1, seg, k, 0.0, SpringFamily::stretch);
  model.gravity = Vec3(0, 0, -9.81);
  model.velocity_damping = 4.0;

  State s = State::at_rest(model);
  DynamicsOptions o;
  o.dt = 1e-4;
  o.steps = 200000;
  o.force_scale = m * 9.81;  // tolerance relative to one particle's weight
  o.tolerance = 1e-5;
  const SolveReport r = run_dynamics(model, s, o);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_FALSE(r.diverged);

  const double a = catenary_parameter(length, half_span);
  const double sag_expected = a * (std::cosh(half_span / a) - 1.0);
  const double sag = -s.x(2, segments / 2);
  EXPECT_NEAR(sag / sag_expected, 1.0, 0.01) << "sag " << sag << " vs " << sag_expected;
  // The chain is symmetric and hangs in its plane.
  EXPECT_NEAR(s.x(0, segments / 2), 0.0, 1e-6);
  EXPECT_NEAR(s.x.row(1).cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

}  // namespace
}  // namespace membra
