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
// strip takes its anticlastic curvature). The shell hinges alone, with their coupling of -1/3,
// buckle it at (8/9)(4/3) = 1.19 times that (1.19 measured); the angle defects bring it down
// towards the plate's (1.16 measured, 1.12 at eight across). The 5 % is not reached yet
// (docs/model.md): held here within 20 %, and the correction's direction.
TEST(ContinuumMechanics, CompressedStripBucklesNearTheEulerStrain) {
  const double length = 0.1, t = 0.5e-3;
  ContinuumSpec spec;
  spec.width = length, spec.height = 0.01;
  spec.mesh.max_edge = 0.0025;
  Sheet s = build_continuum_sheet(spec);
  apply_pins({{PinSpec::Kind::edge, "left"}, {PinSpec::Kind::edge, "right"}}, s.grid, s.model);
  const double euler = std::numbers::pi * std::numbers::pi / 12.0 * (t / length) * (t / length);
  const double with = buckling_strain(s, length, euler) / euler;
  Sheet hinges_only = s;
  for (auto& w : hinges_only.model.angle_defects.weight) w = {0.0, 0.0, 0.0};
  const double without = buckling_strain(hinges_only, length, euler) / euler;
  std::printf("continuum buckling strain / Euler: %.4f, hinges alone %.4f (%d particles)\n", with,
              without, s.model.num_particles());
  EXPECT_NEAR(without, 32.0 / 27.0, 0.02);  // the hinges' coupling, as predicted
  EXPECT_LT(with, without - 0.01);
  EXPECT_NEAR(with, 1.0, 0.2);
}

}  // namespace
}  // namespace membra
