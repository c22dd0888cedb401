// The stability check tells stable equilibria from saddles that also have zero force.
#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/model/membrane.hpp"
#include "membra/solve/stability.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

TEST(Stability, ATautFlatSheetIsStable) {
  Membrane m = make_membrane(build_sheet({0.05, 0.05, 11, 11}, SheetOptions{}));
  stretch_frame(m, 1.2, 1.2);
  const StabilityReport r = check_stability(m.sheet.model, m.state.x, m.sheet.stiffness.stretch);
  EXPECT_TRUE(r.checked);
  EXPECT_TRUE(r.stable) << r.message;
}

TEST(Stability, ACompressedFlatSheetIsASaddle) {
  // Squeezed 10 % on its frame: the flat state has zero force by symmetry, but buckling lowers
  // the energy, so the Hessian has a negative eigenvalue.
  Membrane m = make_membrane(build_sheet({0.05, 0.05, 11, 11}, SheetOptions{}));
  stretch_frame(m, 0.9, 0.9);
  const double k = m.sheet.stiffness.stretch;
  ASSERT_LT(max_residual_force(m.sheet.model, m.state.x), 1e-12 * k);
  const StabilityReport r = check_stability(m.sheet.model, m.state.x, k);
  EXPECT_FALSE(r.stable);
  EXPECT_LT(r.min_eigenvalue, 0.0);
  EXPECT_LE(r.lower_bound, r.min_eigenvalue);
  EXPECT_NE(r.message.find("unstable"), std::string::npos);
  // Once buckled (a bump, then relaxed), the sheet sits in a stable minimum.
  perturb(m, 1e-3, 1);
  StaticOptions o;
  o.force_scale = k * m.sheet.grid.hx();
  o.tolerance = 1e-9;
  ASSERT_TRUE(solve_static(m.sheet.model, m.state, o).converged);
  EXPECT_TRUE(check_stability(m.sheet.model, m.state.x, k).stable);
}

TEST(Stability, AFreeSheetsRigidMotionsDoNotCount) {
  const Sheet s = build_sheet({0.05, 0.05, 6, 6}, SheetOptions{});
  EXPECT_TRUE(check_stability(s.model, s.model.reference, s.stiffness.stretch).stable);
}

}  // namespace
}  // namespace membra
