// The continuum sheet as a plate: a compressed strip buckles at Euler's strain (docs/model.md,
// "Where the continuum model stands").
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "element_checks.hpp"

#include "membra/model/continuum_sheet.hpp"
#include "membra/model/pins.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace {

// Smallest out-of-plane stiffness eigenvalue of the continuum strip compressed flat by `strain`
// between its held ends, after relaxing it in plane.
double continuum_out_of_plane_eigenvalue(const Sheet& s, double strain, double length) {
  Model m = s.model;
  State st = State::at_rest(m);
  for (int p = 0; p < m.num_particles(); ++p)
    if (m.reference(0, p) > length - 1e-12) st.x(0, p) -= strain * length;
  NewtonOptions no;
  no.force_scale = s.stiffness.stretch * s.mesh.mean_edge;
  no.tolerance = 1e-10;
  no.in_plane = true;
  solve_newton(m, st, no);
  return smallest_out_of_plane_eigenvalue(m, st.x);
}

// The strain where the strip held at both ends first buckles, by bisection.
double buckling_strain(const Sheet& s, double length, double guess) {
  double lo = 0.2 * guess, hi = 3.0 * guess;
  EXPECT_GT(continuum_out_of_plane_eigenvalue(s, lo, length), 0.0);
  EXPECT_LT(continuum_out_of_plane_eigenvalue(s, hi, length), 0.0);
  for (int it = 0; it < 12; ++it) {
    const double mid = 0.5 * (lo + hi);
    (continuum_out_of_plane_eigenvalue(s, mid, length) > 0.0 ? lo : hi) = mid;
  }
  return lo;
}

// A 100 x 10 mm latex strip held at both ends, four elements across: Euler's strain for a strip
// of free sides is the beam's, (pi^2/12)(t/L)^2 (the plate's D (1 - nu^2) = E t^3 / 12 once the
// strip takes its anticlastic curvature, which the plate's own nu lets it take). Measured 0.92
// here and 0.95 at eight across (docs/model.md): the triangles along the free sides, whose
// curvature meets a moment-free condition rather than a neighbour, are a little soft, less so as
// they narrow. Held within 10 %, the 5 % reached only on finer meshes.
TEST(ContinuumMechanics, CompressedStripBucklesAtTheEulerStrain) {
  const double length = 0.1, t = 0.5e-3;
  ContinuumSpec spec;
  spec.width = length, spec.height = 0.01;
  spec.mesh.max_edge = 0.0025;
  Sheet s = build_continuum_sheet(spec);
  apply_pins({{PinSpec::Kind::edge, "left"}, {PinSpec::Kind::edge, "right"}}, s.grid, s.model);
  const double euler = std::numbers::pi * std::numbers::pi / 12.0 * (t / length) * (t / length);
  const double ratio = buckling_strain(s, length, euler) / euler;
  std::printf("continuum buckling strain / Euler: %.4f (%d particles)\n", ratio,
              s.model.num_particles());
  EXPECT_NEAR(ratio, 1.0, 0.1);
}

}  // namespace
}  // namespace membra
