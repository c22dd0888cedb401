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

// A disk is held all round its rim (not only where it touches the grid's edges), and a hole's
// rim is left free: the stretch of a disk with a hole is affine, its interior in equilibrium.
TEST(Membrane, TheFrameHoldsADisksRimAndNotAHolesRim) {
  const double r = 0.025;
  auto keep = [r](double x, double y) {
    const double dx = x - r, dy = y - r;
    const double d2 = dx * dx + dy * dy;
    return d2 <= r * r * (1.0 + 1e-9) && d2 >= 0.3 * r * 0.3 * r;
  };
  Membrane m = make_membrane(build_sheet({2 * r, 2 * r, 21, 21}, SheetOptions{}, keep));
  const Points paper = m.state.x;
  const int held = stretch_frame(m, 1.5, 1.5);
  const GridSheet& g = m.sheet.grid;
  int rim = 0, inner_rim = 0;
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const bool missing_neighbour = g.particle(i - 1, j) < 0 || g.particle(i + 1, j) < 0 ||
                                   g.particle(i, j - 1) < 0 || g.particle(i, j + 1) < 0;
    const double d = (paper.col(p) - Vec3(r, r, 0.0)).norm();
    if (missing_neighbour && d > 0.6 * r) {
      ++rim;
      EXPECT_TRUE(m.sheet.model.pinned(p)) << "outer rim node " << i << ", " << j;
    }
    if (missing_neighbour && d < 0.6 * r) {
      ++inner_rim;
      EXPECT_FALSE(m.sheet.model.pinned(p)) << "hole rim node " << i << ", " << j;
    }
  }
  EXPECT_GT(rim, 40);
  EXPECT_GT(inner_rim, 8);
  EXPECT_GE(held, rim);
  // Every particle moved by the stretch, none left behind: uniform strain, so no net force on
  // any particle with all its neighbours (the hole's free rim carries the uniform stress's
  // traction and moves when solved).
  EXPECT_LT((m.state.x - 1.5 * paper).cwiseAbs().maxCoeff(), 1e-15);
  Points f;
  compute_static_forces(m.sheet.model, m.state.x, f);
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    bool full = true;
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) full = full && g.particle(i + di, j + dj) >= 0;
    if (full) {
      EXPECT_LT(f.col(p).norm(), 1e-9 * m.sheet.stiffness.stretch * r) << i << ", " << j;
    }
  }
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

// Resin cured before a second stretch stays: the later pattern's union is taken only with the
// patterns applied since the sheet last moved, and a fraction never falls.
TEST(Membrane, ResinFromBeforeAStretchStays) {
  Membrane m = small_sheet();
  stretch_frame(m, 1.5, 1.0);
  impregnate(m, make_polygon({{-1, -1}, {0.0375, -1}, {0.0375, 1}, {-1, 1}}), epoxy(), +1);
  const std::vector<double> before = m.sheet.model.springs.resin_fraction;
  stretch_frame(m, 1.0, 1.2);
  // A thin band across the resin: the springs it crosses are partly in it, wholly in the first.
  impregnate(m, make_polygon({{0.01, -1}, {0.012, -1}, {0.012, 1}, {0.01, 1}}), epoxy(), +1);
  int crossed = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    EXPECT_GE(m.sheet.model.springs.resin_fraction[i], before[i]) << i;
    crossed += before[i] == 1.0 && m.sheet.model.springs.resin_fraction[i] == 1.0;
  }
  EXPECT_GT(crossed, 0);
  EXPECT_EQ(m.impregnated.size(), 1u);
}

TEST(Membrane, ImpregnatedSpringFollowsTheCompositeRule) {
  Membrane m = small_sheet();
  stretch_frame(m, 1.5, 1.0);
  // Resin over the left half of the frame (x < 0.0375 m, frame coordinates).
  const auto left = make_polygon({{-1, -1}, {0.0375, -1}, {0.0375, 1}, {-1, 1}});
  const Material resin = epoxy();
  EXPECT_GT(impregnate(m, left, resin, +1), 0);
  const Springs& s = m.sheet.model.springs;
  const LatticeStiffness kr = homogenize(resin);
  for (int i = 0; i < s.size(); ++i) {
    if (s.family[i] != SpringFamily::stretch) continue;
    const double f = m.sheet.model.springs.resin_fraction[i];
    const double kl = m.sheet.model.springs.latex_stiffness[i];
    const double krs = kr.stretch * kl / m.sheet.stiffness.stretch;  // half a cell on the boundary
    const double kin = krs + kl;
    if (f == 1.0) {
      // Fully inside: resin and latex in parallel; rest length between the stretched and the
      // natural length, weighted by stiffness.
      EXPECT_NEAR(s.stiffness[i], kin, 1e-9 * kin);
      const double l_now = (m.state.x.col(s.b[i]) - m.state.x.col(s.a[i])).norm();
      EXPECT_NEAR(s.rest_length[i],
                  (krs * l_now + kl * m.sheet.model.springs.natural_length[i]) / kin, 1e-15);
    } else if (f > 0.0) {
      EXPECT_NEAR(s.stiffness[i], 1.0 / ((1 - f) / kl + f / kin), 1e-9 * kin);
    } else {
      EXPECT_EQ(s.stiffness[i], kl);
      EXPECT_EQ(s.rest_length[i], m.sheet.model.springs.natural_length[i]);
    }
  }
  // At the start of the release the sheet is stress-free in its stretched shape.
  begin_release(m);
  EXPECT_LT(max_residual_force(m.sheet.model, m.state.x), 1e-9);
}

}  // namespace
}  // namespace membra
