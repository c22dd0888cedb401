// Extrinsic deformation: springs added beside the lattice's pull the sheet together where they
// are, and keep their rest length through a release.
#include <gtest/gtest.h>

#include "membra/model/added_springs.hpp"
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
  const int added = add_springs(m, spec);
  // Stretch springs in the top half: 10 rows of 20 along x, 10 x 21 along y (those crossing the
  // region's edge at y = 20.5 mm lie half inside and count).
  EXPECT_EQ(added, 3 * (10 * 20 + 10 * 21));
  EXPECT_EQ(m.sheet.model.springs.size(), lattice + added / 3);
  EXPECT_EQ(m.sheet.model.springs.natural_length.size(),
            static_cast<size_t>(m.sheet.model.springs.size()));
  for (int s = lattice; s < m.sheet.model.springs.size(); ++s) {
    EXPECT_EQ(m.sheet.model.springs.family[s], SpringFamily::added);
    EXPECT_DOUBLE_EQ(m.sheet.model.springs.stiffness[s], 3 * spec.stiffness);
  }
  // A release does not touch them.
  begin_release(m);
  set_release_level(m, 0.0);
  EXPECT_NEAR(m.sheet.model.springs.rest_length[lattice], 0.8 * 0.002, 1e-15);

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
  EXPECT_THROW(add_springs(m, spec), std::invalid_argument);
}

}  // namespace
}  // namespace membra
