// Extrinsic deformation: springs added beside the lattice's pull the sheet together where they
// are, and keep their rest length through a release.
#include <gtest/gtest.h>

#include "membra/model/elements/added_springs.hpp"
#include "membra/model/grow.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

TEST(AddSprings, ShortSpringsContractTheirRegionOnly) {
  Membrane m = make_membrane(build_sheet({0.04, 0.04, 21, 21}, SheetOptions{}));
  const int lattice = m.sheet.model.springs.size();
  AddSpringsSpec spec;
  spec.region = make_polygon({{-1, 0.0205}, {1, 0.0205}, {1, 1}, {-1, 1}});  // the top half
  spec.along = SpringFamily::stretch;
  spec.count = 3;
  spec.stiffness = m.sheet.stiffness.stretch;
  spec.rest_factor = 0.8;
  AddedSprings& as = m.sheet.model.added_springs;
  const int added = as.add_beside(m.sheet.model.springs, m.state.x, spec);
  // Stretch springs in the top half: 10 rows of 20 along x, 10 x 21 along y (those crossing the
  // region's edge at y = 20.5 mm lie half inside and count).
  EXPECT_EQ(added, 3 * (10 * 20 + 10 * 21));
  EXPECT_EQ(as.size(), added / 3);
  EXPECT_EQ(m.sheet.model.springs.size(), lattice);  // a set of their own
  for (int s = 0; s < as.size(); ++s) EXPECT_DOUBLE_EQ(as.stiffness[s], 3 * spec.stiffness);
  // A release does not touch them; the path's level moves them from their length to 0.8 of it.
  begin_release(m);
  set_release_level(m, 0.0);
  EXPECT_NEAR(as.rest_length[0], 0.8 * 0.002, 1e-15);
  as.set_level(0, spec.rest_factor, 0.5);
  EXPECT_NEAR(as.rest_length[0], 0.9 * 0.002, 1e-15);
  as.set_level(0, spec.rest_factor, 1.0);

  StaticOptions o;
  o.force_scale = m.sheet.stiffness.stretch * 0.002;
  ASSERT_TRUE(solve_static(m.sheet.model, m.state, o).converged);
  const GridSheet& g = m.sheet.grid;
  auto width = [&](int j) {
    return m.state.x(0, g.particle(20, j)) - m.state.x(0, g.particle(0, j));
  };
  // Four lattice-strengths at 0.8 against one at 1: the top edge shrinks to about 0.84.
  EXPECT_NEAR(width(20) / 0.04, (3 * 0.8 + 1.0) / 4.0, 0.02);
  EXPECT_GT(width(0) / 0.04, 0.95);  // the bottom edge stays close to its length

  spec.rest_factor = 0.0;
  EXPECT_THROW(as.add_beside(m.sheet.model.springs, m.state.x, spec), std::invalid_argument);
}

TEST(AddSprings, AGrowthOfTheirFamilyScalesThemAloneAndACutSeversThem) {
  Membrane m = make_membrane(build_sheet({0.04, 0.04, 5, 5}, SheetOptions{}));
  AddSpringsSpec spec;
  spec.region = make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  spec.stiffness = 1.0;
  AddedSprings& as = m.sheet.model.added_springs;
  ASSERT_GT(as.add_beside(m.sheet.model.springs, m.state.x, spec), 0);
  const std::vector<double> rest = as.rest_length, lattice = m.sheet.model.springs.rest_length;
  GrowSpec g;
  g.factor = [](const Vec2&) { return 1.5; };
  g.family = SpringFamily::added;
  apply_growth(m, plan_growth(m.sheet.model, PatternGrowth(g)), 1.0);
  for (int s = 0; s < as.size(); ++s) EXPECT_DOUBLE_EQ(as.rest_length[s], 1.5 * rest[s]);
  EXPECT_EQ(m.sheet.model.springs.rest_length, lattice);
  // The springs' read-out: strain and force, no stress of the sheet's.
  const ElementStress e = as.stress(0, m.state.x, 1e-3);
  EXPECT_TRUE(e.strained && e.axial && !e.carries);
  EXPECT_NEAR(e.strain, 1.0 / 1.5 - 1.0, 1e-12);
  const int before = as.size();
  as.filter(survivors_of_cut(as, [](int p, int q) { return p == 0 || q == 0; }));
  EXPECT_LT(as.size(), before);
}

}  // namespace
}  // namespace membra
