// Cuts and holes: what they remove, what they keep, and the mechanics of a cut strip.
#include <gtest/gtest.h>

#include <numeric>

#include "membra/model/cut.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

double total_mass(const Model& m) {
  return std::accumulate(m.mass.begin(), m.mass.end(), 0.0);
}

TEST(Cut, CuttingAPretensionedStripLetsBothPartsReturnToNaturalLength) {
  // A 20 x 4 mm strip (21 x 5 nodes) stretched 1.2x between grips on its short ends, then cut
  // across between columns 10 and 11: each half hangs from one grip, free at the cut.
  Membrane m = make_membrane(build_sheet({0.02, 0.004, 21, 5}, SheetOptions{}));
  stretch_frame(m, 1.2, 1.0, FrameEdges{true, true, false, false});
  const double h = 0.001, x_cut = 1.2 * 10.5 * h;
  const int removed = cut_along(m, {{x_cut, -0.01}, {x_cut, 0.02}});
  EXPECT_EQ(removed, 5 + 2 * 4);  // the x springs of 5 rows and both diagonals of 4 cells
  // No spring joins the two halves any more.
  const Springs& sp = m.sheet.model.springs;
  for (int s = 0; s < sp.size(); ++s) {
    const int ia = m.sheet.grid.node(sp.a[s]).first, ib = m.sheet.grid.node(sp.b[s]).first;
    EXPECT_EQ(ia <= 10, ib <= 10) << "spring " << s;
  }
  StaticOptions o;
  o.force_scale = m.sheet.stiffness.stretch * h;
  o.tolerance = 1e-10;
  ASSERT_TRUE(solve_static(m.sheet.model, m.state, o).converged);
  const GridSheet& g = m.sheet.grid;
  for (int j = 0; j < 5; ++j) {
    const double left = m.state.x(0, g.particle(10, j)) - m.state.x(0, g.particle(0, j));
    const double right = m.state.x(0, g.particle(20, j)) - m.state.x(0, g.particle(11, j));
    EXPECT_NEAR(left / (10 * h), 1.0, 1e-6) << "row " << j;
    EXPECT_NEAR(right / (9 * h), 1.0, 1e-6) << "row " << j;
  }
}

TEST(Cut, ACutThatMissesTheSheetRemovesNothing) {
  Membrane m = make_membrane(build_sheet({0.02, 0.02, 5, 5}, SheetOptions{}));
  EXPECT_EQ(cut_along(m, {{0.03, 0.0}, {0.04, 0.02}}), 0);
  EXPECT_THROW(cut_along(m, {{0.01, 0.01}}), std::invalid_argument);
}

TEST(Cut, AHoleRemovesParticlesAndRebuildsTheEdge) {
  const double size = 0.02, h = 0.001;
  Membrane m = make_membrane(build_sheet({size, size, 21, 21}, SheetOptions{}));
  const double mass0 = total_mass(m.sheet.model);
  // An earlier cut must stay cut after the rebuild.
  const int cut = cut_along(m, {{0.0025, 0.0005}, {0.0025, 0.0055}});
  ASSERT_GT(cut, 0);
  const int springs_before = m.sheet.model.springs.size();
  const size_t triangles_before = m.sheet.triangles.size();
  EXPECT_LT(triangles_before, 800u);  // the cut took the triangles it crosses
  // A 4 x 4 mm square hole in the middle removes 5 x 5 nodes (x, y in 8..12 mm).
  const auto square =
      make_polygon({{0.0075, 0.0075}, {0.0125, 0.0075}, {0.0125, 0.0125}, {0.0075, 0.0125}});
  EXPECT_EQ(punch_hole(m, *square), 25);
  const Model& model = m.sheet.model;
  EXPECT_EQ(model.num_particles(), 21 * 21 - 25);
  // The 6 x 6 cells around the removed nodes are gone: their mass is too.
  const double cell_mass = h * h * m.sheet.material.thickness * m.sheet.material.density;
  EXPECT_NEAR(total_mass(model), mass0 - 36 * cell_mass, 1e-12 * mass0);
  EXPECT_EQ(m.sheet.triangles.size(), triangles_before - 2 * 36);
  // The springs along the new edge carry half a cell, like the sheet's outer edge.
  const GridSheet& g = m.sheet.grid;
  const Springs& sp = model.springs;
  const double k = m.sheet.stiffness.stretch;
  int edge = 0;
  for (int s = 0; s < sp.size(); ++s) {
    const auto [ia, ja] = g.node(sp.a[s]);
    const auto [ib, jb] = g.node(sp.b[s]);
    if (ja == 7 && jb == 7 && ia >= 7 && ib <= 13) {
      EXPECT_NEAR(sp.stiffness[s], 0.5 * k, 1e-9 * k);
      ++edge;
    }
  }
  EXPECT_EQ(edge, 6);
  // The cut springs did not come back; fewer springs than before the hole.
  EXPECT_LT(sp.size(), springs_before);
  for (int s = 0; s < sp.size(); ++s) {
    const Vec2 a = model.reference.col(sp.a[s]).head<2>(),
               b = model.reference.col(sp.b[s]).head<2>();
    if ((a.x() < 0.0025) == (b.x() < 0.0025)) continue;
    const double y = a.y() + (b.y() - a.y()) * (0.0025 - a.x()) / (b.x() - a.x());
    EXPECT_FALSE(y >= 0.0005 && y <= 0.0055) << "spring " << s << " crosses the earlier cut";
  }
  // Triangles only use existing particles; an all-covering hole is refused.
  for (const Triangle& t : m.sheet.triangles)
    for (int c = 0; c < 3; ++c) EXPECT_LT(t[c], model.num_particles());
  const auto everything = make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  EXPECT_THROW(punch_hole(m, *everything), std::invalid_argument);
}

}  // namespace
}  // namespace membra
