// The process steps on small sheets: stretch, impregnate (composite rule), release.
#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/model/membrane.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

Membrane small_sheet() {
  return make_membrane(build_sheet({0.05, 0.05, 11, 11}, SheetOptions{}));
}

TEST(Membrane, StretchIsAffineAndInEquilibriumOnAFullGrid) {
  Membrane m = small_sheet();
  EXPECT_EQ(stretch_frame(m, 1.5, 1.2), 40);  // the outer ring of an 11 x 11 grid
  EXPECT_NEAR(m.state.x(0, m.sheet.grid.particle(10, 3)), 0.075, 1e-15);
  EXPECT_NEAR(m.state.x(1, m.sheet.grid.particle(3, 10)), 0.06, 1e-15);
  // Uniform strain: interior forces cancel exactly.
  EXPECT_LT(max_residual_force(m.sheet.model, m.state.x), 1e-12);
  EXPECT_THROW(stretch_frame(m, 0.0, 1.0), std::invalid_argument);
}

TEST(Membrane, ReleaseWithoutResinReturnsToNaturalSizeAndStaysFlat) {
  Membrane m = small_sheet();
  stretch_frame(m, 1.5, 1.0);
  perturb(m, 1e-5, 3);
  begin_release(m);
  StaticOptions o;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  for (int k = 1; k <= 5; ++k) {
    set_release_level(m, 1.0 - k / 5.0);
    ASSERT_TRUE(solve_static(m.sheet.model, m.state, o).converged);
  }
  const Points& x = m.state.x;
  const Vec3 size = x.rowwise().maxCoeff() - x.rowwise().minCoeff();
  EXPECT_NEAR(size.x() / 0.05, 1.0, 0.005);
  EXPECT_NEAR(size.y() / 0.05, 1.0, 0.005);
  EXPECT_LT(size.z(), 1e-3 * 0.05);
}

TEST(Membrane, ImpregnatedSpringFollowsTheCompositeRule) {
  Membrane m = small_sheet();
  stretch_frame(m, 1.5, 1.0);
  // Resin over the left half of the frame (x < 0.0375 m, frame coordinates).
  const auto left = make_polygon({{-1, -1}, {0.0375, -1}, {0.0375, 1}, {-1, 1}});
  const Material resin = epoxy();
  EXPECT_GT(impregnate(m, *left, resin, +1), 0);
  const Springs& s = m.sheet.model.springs;
  const LatticeStiffness kr = homogenize(resin);
  for (int i = 0; i < s.size(); ++i) {
    if (s.family[i] != SpringFamily::stretch) continue;
    const double f = m.resin_fraction[i];
    const double kl = m.latex_stiffness[i];
    const double krs = kr.stretch * kl / m.sheet.stiffness.stretch;  // half a cell on the boundary
    const double kin = krs + kl;
    if (f == 1.0) {
      // Fully inside: resin and latex in parallel; rest length between the stretched and the
      // natural length, weighted by stiffness.
      EXPECT_NEAR(s.stiffness[i], kin, 1e-9 * kin);
      const double l_now = (m.state.x.col(s.b[i]) - m.state.x.col(s.a[i])).norm();
      EXPECT_NEAR(s.rest_length[i], (krs * l_now + kl * m.natural_length[i]) / kin, 1e-15);
    } else if (f > 0.0) {
      EXPECT_NEAR(s.stiffness[i], 1.0 / ((1 - f) / kl + f / kin), 1e-9 * kin);
    } else {
      EXPECT_EQ(s.stiffness[i], kl);
      EXPECT_EQ(s.rest_length[i], m.natural_length[i]);
    }
  }
  // At the start of the release the sheet is stress-free in its stretched shape.
  begin_release(m);
  EXPECT_LT(max_residual_force(m.sheet.model, m.state.x), 1e-9);
}

}  // namespace
}  // namespace membra
