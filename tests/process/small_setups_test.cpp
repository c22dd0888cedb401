// The set-ups of the full-size physics tests, scaled down so that the sanitized run
// (scripts/check-sanitized) checks their code paths too: a hole in a stretched plate solved in
// plane with its stress tensor and edge extrapolation (Kirsch's test: 181 x 181), a hanging chain
// settled by damped dynamics (the catenary: 40 segments, 2e5 steps), and the force pass split into
// chunks that sheets of 2000 particles and more take (the determinism test, at 64 x 64 and
// larger). The numbers are checked loosely here: the full-size tests check them tightly.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "membra/measure/hole_edge.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/cut.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/dynamics.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace {

// Kirsch's plate on a 61 x 61 grid: a hole of 6.5 spacings (the least the edge extrapolation
// takes), uniaxial tension in plane. The peak hoop stress, extrapolated to the edge, is three times
// the far field within the full-size test's 15 % (a plate under five hole diameters wide).
TEST(SmallSetups, AHoleInAStretchedPlateConcentratesStress) {
  constexpr int n = 61, c = 30;
  constexpr double h = 1e-3;
  SheetOptions o;
  o.bending = false;
  Membrane m = make_membrane(build_sheet({(n - 1) * h, (n - 1) * h, n, n}, o));
  std::vector<Vec2> removed;
  ASSERT_GT(punch_hole(m, *make_ellipse(Vec2(c * h, c * h), 6.5 * h, 6.5 * h, 0.0), &removed), 100);
  const double e = 1e-3;
  stretch_frame(m, 1.0 + e, 1.0 - e / 3.0, FrameEdges{true, true, false, false});
  NewtonOptions no;
  no.force_scale = m.sheet.stiffness.stretch * h;
  no.tolerance = 1e-9;
  no.in_plane = true;
  const SolveReport r = solve_newton(m.sheet.model, m.state, no);
  ASSERT_TRUE(r.converged) << r.message;
  const NodeStress s =
      node_stress(m.sheet.grid, m.sheet.model, m.state.x, m.sheet.material.thickness);
  const double far = s.sigma[static_cast<size_t>(m.sheet.grid.particle(c, 3))](0, 0);
  ASSERT_GT(far, 0.0);
  const HoleEdge edge = hole_edge(m.sheet.grid, max_principal_stress(s), removed);
  ASSERT_TRUE(edge.valid);
  EXPECT_TRUE(std::isfinite(edge.value));
  std::printf("edge / far field: %.3f (Kirsch 3)\n", edge.value / far);
  EXPECT_NEAR(edge.value / far, 3.0, 0.15 * 3.0);  // the full-size test's 15 % (measured 2.81)
}

// A chain of 10 stiff springs hanging between two pins, settled by damped dynamics: its sag is the
// catenary's within 2 % (measured 0.5 %; 40 links: within 1 %).
TEST(SmallSetups, AHangingChainSettlesNearTheCatenary) {
  const int segments = 10;
  const double length = 1.2, half_span = 0.5, seg = length / segments, mass = 0.1 * seg;
  Model model;
  for (int i = 0; i <= segments; ++i) {
    const double x = -half_span + 2.0 * half_span * i / segments;
    model.add_particle(mass, Vec3(x, 0.0, -0.3 * (1.0 - (x / half_span) * (x / half_span))));
  }
  model.pin(0);
  model.pin(segments);
  for (int i = 0; i < segments; ++i)
    model.springs.add(i, i + 1, seg, 1e4 / seg, 0.0, SpringFamily::stretch);
  model.gravity = Vec3(0, 0, -9.81);
  model.velocity_damping = 4.0;
  State st = State::at_rest(model);
  DynamicsOptions o;
  o.dt = 1e-4;
  o.steps = 100000;
  o.force_scale = mass * 9.81;
  o.tolerance = 1e-4;
  const SolveReport r = run_dynamics(model, st, o);
  ASSERT_TRUE(r.converged) << r.message;
  // The catenary of this length and span: a = 0.3356 m (L = 2 a sinh(b / a)), sag a (cosh(b/a)-1).
  double lo = 1e-3, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2.0 * a * std::sinh(half_span / a) > length ? lo : hi) = a;
  }
  const double sag = lo * (std::cosh(half_span / lo) - 1.0);
  std::printf("sag / catenary: %.4f\n", -st.x(2, segments / 2) / sag);
  EXPECT_NEAR(-st.x(2, segments / 2) / sag, 1.0, 0.02);
}

// A 47 x 47 sheet (2209 particles: the force pass splits its elements into chunks, each summed
// into its own buffer band) in a random, compressed configuration: the same forces bit for bit
// with one thread and with two, and the same as the energy's decrease along them.
TEST(SmallSetups, TheChunkedForcePassIsTheSameOnAnyThreadCount) {
  Sheet sheet = build_sheet({0.046, 0.046, 47, 47}, SheetOptions{});
  Model m = sheet.model;
  for (auto& l0 : m.springs.rest_length) l0 *= 0.9;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points x = m.reference;
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] += 1e-4 * u(rng);
  const int threads = omp_get_max_threads();
  Points f1, f2;
  omp_set_num_threads(1);
  compute_static_forces(m, x, f1);
  omp_set_num_threads(2);
  compute_static_forces(m, x, f2);
  omp_set_num_threads(threads);
  ASSERT_TRUE(f1.allFinite());
  EXPECT_EQ(f1, f2);
  // The forces are minus the energy's gradient: a small step along them lowers the energy by
  // about |f|^2 times the step.
  const double step = 1e-12;
  const double drop = potential_energy(m, x) - potential_energy(m, x + step * f1);
  EXPECT_NEAR(drop / (step * f1.squaredNorm()), 1.0, 1e-3);
}

}  // namespace
}  // namespace membra
