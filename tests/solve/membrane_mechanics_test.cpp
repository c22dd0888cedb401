// The lattice as a continuum: uniaxial tension gives E t and nu = 1/3 (docs/model.md,
// "Homogenization"), and a compressed strip buckles at Euler's load with the plate bending
// stiffness.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "element_checks.hpp"

#include "membra/measure/stress.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

TEST(Mechanics, UniaxialTensionGivesEtAndPoissonOneThird) {
  const double length = 0.2, width = 0.04, strain = 1e-3;
  SheetOptions o;
  o.bending = false;  // a pure membrane
  Sheet s = build_sheet({length, width, 51, 11}, o);
  Model& m = s.model;
  apply_pins({{PinSpec::Kind::edge, "left"}, {PinSpec::Kind::edge, "right"}}, s.grid, m);
  State st = State::at_rest(m);
  for (int j = 0; j < 11; ++j) st.x(0, s.grid.particle(50, j)) += strain * length;
  NewtonOptions no;
  no.force_scale = s.stiffness.stretch * s.grid.hx();
  no.tolerance = 1e-10;
  no.in_plane = true;  // a membrane without bending would wrinkle wherever it is compressed
  ASSERT_TRUE(solve_newton(m, st, no).converged);

  // Reaction at the right clamp = force carried through any section.
  Points f;
  compute_static_forces(m, st.x, f);
  double force = 0.0;
  for (int j = 0; j < 11; ++j) force -= f(0, s.grid.particle(50, j));
  // Strains in the middle, away from the clamps.
  const auto x = [&](int i, int j) { return Vec3(st.x.col(s.grid.particle(i, j))); };
  const double ex = (x(30, 5).x() - x(20, 5).x()) / (10 * s.grid.hx()) - 1.0;
  const double ey = (x(25, 10).y() - x(25, 0).y()) / width - 1.0;
  const double et = force / width / ex;
  EXPECT_NEAR(et / membrane_stiffness_from_stretch(s.stiffness.stretch), 1.0, 0.02);
  EXPECT_NEAR(et / (1.5e6 * 0.5e-3), 1.0, 0.02);
  EXPECT_NEAR(-ey / ex, 1.0 / 3.0, 0.02);

  // Spring stress (force over tributary width x thickness): a stretch spring along the load
  // carries k ex h over width h, i.e. 3/4 of the continuum stress E ex (the diagonals carry the
  // rest); tension is positive.
  for (int i = 0; i < m.springs.size(); ++i) {
    const auto [ia, ja] = s.grid.node(m.springs.a[i]);
    const auto [ib, jb] = s.grid.node(m.springs.b[i]);
    if (ia == 25 && ja == 5 && ib == 26 && jb == 5) {
      const ElementStress e = m.springs.stress(i, st.x, 0.5e-3);
      EXPECT_NEAR(e.stress / (0.75 * 1.5e6 * ex), 1.0, 0.01);
      EXPECT_NEAR(e.strain / ex, 1.0, 0.01);
    }
  }
  EXPECT_GT(stress_ranges(m, st.x, 0.5e-3).max_stress, 0.0);
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

// Smallest out-of-plane stiffness eigenvalue (z coordinates of free particles) of a strip
// compressed flat by `strain` between pinned ends, after relaxing it in plane.
double strip_out_of_plane_eigenvalue(const Sheet& s, double strain, double length) {
  Model m = s.model;
  State st = State::at_rest(m);
  const int nx = s.grid.nx();
  for (int j = 0; j < s.grid.ny(); ++j) st.x(0, s.grid.particle(nx - 1, j)) -= strain * length;
  // FIRE stays exactly flat (nothing pushes out of plane), so it relaxes the strip in plane; Newton
  // would leave the flat saddle along negative curvature, as it should.
  StaticOptions so;
  so.force_scale = s.stiffness.stretch * s.grid.hx();
  so.tolerance = 1e-10;
  solve_static(m, st, so);
  return smallest_out_of_plane_eigenvalue(m, st.x);
}

TEST(Mechanics, CompressedStripBucklesAtTheEulerStrain) {
  const double length = 0.1, width = 0.01, t = 0.5e-3;
  Sheet s = build_sheet({length, width, 41, 5}, SheetOptions{});
  apply_pins({{PinSpec::Kind::edge, "left"}, {PinSpec::Kind::edge, "right"}}, s.grid, s.model);
  const double expected = std::numbers::pi * std::numbers::pi / 12.0 * (t / length) * (t / length);
  // Bisection on the strain where the flat strip loses its out-of-plane stiffness.
  double lo = 0.2 * expected, hi = 3.0 * expected;
  ASSERT_GT(strip_out_of_plane_eigenvalue(s, lo, length), 0.0);
  ASSERT_LT(strip_out_of_plane_eigenvalue(s, hi, length), 0.0);
  for (int it = 0; it < 14; ++it) {
    const double mid = 0.5 * (lo + hi);
    (strip_out_of_plane_eigenvalue(s, mid, length) > 0.0 ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo / expected, 1.0, 0.10) << "critical strain " << lo << ", Euler " << expected;
  std::printf("buckling strain %.4g, Euler (pi^2/12)(t/L)^2 = %.4g, ratio %.4f\n", lo, expected,
              lo / expected);
}

}  // namespace
}  // namespace membra
