// The lattice as a continuum: uniaxial tension gives E t and nu = 1/3 (DESIGN.md section 3),
// and a compressed strip buckles at Euler's load with the plate bending stiffness.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/sheet.hpp"
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
}

}  // namespace
}  // namespace membra
