// Building a sheet model: springs per family, lumped masses, pins.
#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/sheet.hpp"

namespace membra {
namespace {

int count(const Springs& s, SpringFamily f) {
  int n = 0;
  for (auto g : s.family) n += g == f ? 1 : 0;
  return n;
}

TEST(Sheet, SpringFamiliesOnAFullGrid) {
  SheetOptions o;
  o.flex = true;
  const int nx = 7, ny = 5;
  const Sheet s = build_sheet({0.06, 0.04, nx, ny}, o);
  EXPECT_EQ(s.model.num_particles(), nx * ny);
  EXPECT_EQ(count(s.model.springs, SpringFamily::stretch), (nx - 1) * ny + nx * (ny - 1));
  EXPECT_EQ(count(s.model.springs, SpringFamily::shear), 2 * (nx - 1) * (ny - 1));
  EXPECT_EQ(count(s.model.springs, SpringFamily::flex), (nx - 2) * ny + nx * (ny - 2));
  EXPECT_EQ(s.triangles.size(), 2u * (nx - 1) * (ny - 1));
  // Springs start at rest: no force anywhere.
  Points f;
  compute_static_forces(s.model, s.model.reference, f);
  EXPECT_LT(f.norm(), 1e-12);
  for (int i = 0; i < s.model.springs.size(); ++i) {
    const double expected = s.model.springs.family[i] == SpringFamily::shear ? 0.01 * std::sqrt(2.0)
                            : s.model.springs.family[i] == SpringFamily::flex ? 0.02
                                                                              : 0.01;
    EXPECT_NEAR(s.model.springs.rest_length[i], expected, 1e-15);
  }
}

TEST(Sheet, LumpedMassesAddUpToAreaTimesThicknessTimesDensity) {
  const Sheet s = build_sheet({0.2, 0.1, 21, 11}, SheetOptions{});
  double total = 0.0;
  for (double m : s.model.mass) total += m;
  EXPECT_NEAR(total, 0.2 * 0.1 * 0.5e-3 * 930.0, 1e-15);
  // Corner, edge and interior masses are 1/4, 1/2 and 1 cell.
  const double cell = 0.01 * 0.01 * 0.5e-3 * 930.0;
  EXPECT_NEAR(s.model.mass[s.grid.particle(0, 0)], cell / 4, 1e-18);
  EXPECT_NEAR(s.model.mass[s.grid.particle(5, 0)], cell / 2, 1e-18);
  EXPECT_NEAR(s.model.mass[s.grid.particle(5, 5)], cell, 1e-18);
}

TEST(Sheet, StiffnessOverrideKeepsFamilyRatios) {
  SheetOptions o;
  o.stretch_stiffness = 100.0;
  const Sheet s = build_sheet({0.02, 0.02, 3, 3}, o);
  EXPECT_DOUBLE_EQ(s.stiffness.stretch, 100.0);
  EXPECT_DOUBLE_EQ(s.stiffness.shear, 50.0);
}

TEST(Sheet, HoleRemovesParticlesAndSprings) {
  const auto keep = [](double x, double y) {
    return !(x > 0.035 && x < 0.065 && y > 0.035 && y < 0.065);
  };
  const Sheet full = build_sheet({0.1, 0.1, 11, 11}, SheetOptions{});
  const Sheet holed = build_sheet({0.1, 0.1, 11, 11}, SheetOptions{}, keep);
  EXPECT_EQ(holed.model.num_particles(), 121 - 9);
  EXPECT_EQ(holed.triangles.size(), full.triangles.size() - 2u * 16);
  for (int i = 0; i < holed.model.springs.size(); ++i) {
    EXPECT_LT(holed.model.springs.a[i], holed.model.num_particles());
    EXPECT_LT(holed.model.springs.b[i], holed.model.num_particles());
  }
}

TEST(Sheet, RejectsNonPositiveMaterial) {
  SheetOptions o;
  o.material.youngs_modulus = -1.0;
  EXPECT_THROW(build_sheet({0.1, 0.1, 3, 3}, o), std::invalid_argument);
}

TEST(Pins, CornersEdgesPointsAndBoxes) {
  Sheet s = build_sheet({0.1, 0.1, 11, 11}, SheetOptions{});
  PinSpec corners;
  PinSpec left{PinSpec::Kind::edge, "left"};
  PinSpec point;
  point.kind = PinSpec::Kind::point;
  point.point = Vec2(0.052, 0.049);  // nearest node (5, 5)
  EXPECT_EQ(apply_pins({corners, left, point}, s.grid, s.model), 4 + 11 - 2 + 1);
  EXPECT_TRUE(s.model.pinned(s.grid.particle(5, 5)));
  EXPECT_TRUE(s.model.pinned(s.grid.particle(10, 10)));
  EXPECT_FALSE(s.model.pinned(s.grid.particle(9, 10)));
  PinSpec empty_box;
  empty_box.kind = PinSpec::Kind::box;
  empty_box.box_min = Vec2(0.031, 0.031);
  empty_box.box_max = Vec2(0.039, 0.039);
  EXPECT_THROW(apply_pins({empty_box}, s.grid, s.model), std::invalid_argument);
}

}  // namespace
}  // namespace membra
