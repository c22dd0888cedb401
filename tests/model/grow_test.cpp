// Intrinsic deformation: growth ratios along directions, and the released form of a grown sheet,
// on the lattice and on the continuum sheet.
#include <gtest/gtest.h>

#include <cmath>

#include "membra/model/continuum_sheet.hpp"
#include "membra/model/grow.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

Membrane sheet(int n, double size = 0.05) {
  return make_membrane(build_sheet({size, size, n, n}, SheetOptions{}));
}

// Each spring's length ratio under the growth (the springs are the model's first set).
std::vector<double> growth_ratios(const Membrane& m, const GrowSpec& g) {
  const GrowthPlan plan = plan_growth(m.sheet.model, PatternGrowth(g));
  const Springs& sp = m.sheet.model.springs;
  const Points& r = m.sheet.model.reference;
  std::vector<double> ratio;
  for (int s = 0; s < sp.size(); ++s)
    ratio.push_back(plan.per_set[0][static_cast<size_t>(s)].ratio(r.col(sp.b[s]).head<2>() -
                                                                  r.col(sp.a[s]).head<2>()));
  return ratio;
}

int spring_between(const Membrane& m, int pi, int pj, int qi, int qj) {
  const GridSheet& g = m.sheet.grid;
  const int a = g.particle(pi, pj), b = g.particle(qi, qj);
  const Springs& sp = m.sheet.model.springs;
  for (int s = 0; s < sp.size(); ++s)
    if ((sp.a[s] == a && sp.b[s] == b) || (sp.a[s] == b && sp.b[s] == a)) return s;
  return -1;
}

// Grows every length of m by s in four increments, relaxing after each, and returns how far
// (m) the released sheet is from the first one scaled by s about its centroid: with no gravity
// and no pins that scaled sheet is the unique stress-free shape (up to a rigid motion).
double uniform_growth_error(Membrane& m, double s, double force_scale) {
  const Points x0 = m.state.x;
  GrowSpec g;
  g.factor = [s](const Vec2&) { return s; };
  const GrowthPlan plan = plan_growth(m.sheet.model, PatternGrowth(g));
  StaticOptions o;
  o.force_scale = force_scale;
  o.tolerance = 1e-12;
  for (int k = 1; k <= 4; ++k) {
    apply_growth(m, plan, 0.25);
    if (!solve_static(m.sheet.model, m.state, o).converged) return 1.0;
  }
  const Vec3 c0 = x0.rowwise().mean(), c = m.state.x.rowwise().mean();
  double worst = 0.0;
  for (int p = 0; p < m.sheet.model.num_particles(); ++p)
    worst = std::max(worst, (m.state.x.col(p) - c - s * (x0.col(p) - c0)).norm());
  return worst;
}

TEST(Grow, DirectionalFactorsFollowTheMetric) {
  const Membrane m = sheet(5);
  GrowSpec g;
  g.factor = [](const Vec2&) { return 2.0; };
  g.direction = GrowDirection::y;
  const auto r = growth_ratios(m, g);
  EXPECT_DOUBLE_EQ(r[spring_between(m, 1, 1, 2, 1)], 1.0);                     // along x: unchanged
  EXPECT_DOUBLE_EQ(r[spring_between(m, 1, 1, 1, 2)], 2.0);                     // along y: doubled
  EXPECT_NEAR(r[spring_between(m, 1, 1, 2, 2)], std::sqrt(5.0 / 2.0), 1e-12);  // (1, 2) / (1, 1)

  // Radial about the centre: a spring pointing away from it grows, one around it does not.
  g.direction = GrowDirection::radial;
  g.center = Vec2(0.025, 0.025);
  const auto rr = growth_ratios(m, g);
  EXPECT_NEAR(rr[spring_between(m, 3, 2, 4, 2)], 2.0, 1e-12);
  EXPECT_NEAR(rr[spring_between(m, 4, 2, 4, 3)],
              std::hypot(2.0 * std::sin(std::atan(0.25)), std::cos(std::atan(0.25))), 1e-12);
  g.direction = GrowDirection::hoop;
  EXPECT_NEAR(growth_ratios(m, g)[spring_between(m, 3, 2, 4, 2)], 1.0, 1e-12);

  // A family filter and a region leave the rest alone.
  g.direction = GrowDirection::all;
  g.family = SpringFamily::shear;
  const auto rs = growth_ratios(m, g);
  EXPECT_DOUBLE_EQ(rs[spring_between(m, 1, 1, 2, 1)], 1.0);
  EXPECT_DOUBLE_EQ(rs[spring_between(m, 1, 1, 2, 2)], 2.0);
}

TEST(Grow, RejectsNonPositiveFactors) {
  const Membrane m = sheet(5);
  GrowSpec g;
  g.factor = [](const Vec2& p) { return p.x() < 0.03 ? 1.0 : -0.5; };
  try {
    growth_ratios(m, g);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("-0.5"), std::string::npos) << e.what();
  }
}

TEST(Grow, UniformFactorScalesTheReleasedSheet) {
  // With no gravity and no pins, growing every rest length by s has the sheet scaled by s as its
  // unique stress-free shape (up to a rigid motion).
  Membrane m = sheet(11);
  EXPECT_LT(uniform_growth_error(m, 1.25, m.sheet.stiffness.stretch * m.sheet.grid.hx()),
            1e-6 * 0.05);
}

Membrane continuum_sheet() {
  ContinuumSpec s;
  s.width = s.height = 0.04;
  s.mesh.max_edge = 0.006;
  return make_membrane(build_continuum_sheet(s));
}

TEST(Grow, TrianglesTakeTheGrownPapersMetric) {
  // After the whole growth, each triangle's natural metric is that of its paper corners moved by
  // the growth's stretch (along x by 1.3 here), and its area (the latex's volume) grew with it.
  Membrane m = continuum_sheet();
  const MembraneTriangles before = m.sheet.model.membrane_triangles;
  GrowSpec g;
  g.factor = [](const Vec2&) { return 1.3; };
  g.direction = GrowDirection::x;
  const GrowthPlan plan = plan_growth(m.sheet.model, PatternGrowth(g));
  for (int k = 0; k < 4; ++k) apply_growth(m, plan, 0.25);
  const MembraneTriangles& t = m.sheet.model.membrane_triangles;
  const Points& r = m.sheet.model.reference;
  const Eigen::Matrix3d a = Eigen::Vector3d(1.3, 1.0, 1.0).asDiagonal();
  ASSERT_GT(t.size(), 20);
  for (int i = 0; i < t.size(); ++i) {
    const auto p = t.ids(i);
    const Eigen::Matrix2d want = triangle_metric(a * r.col(p[0]), a * r.col(p[1]), a * r.col(p[2]));
    EXPECT_LT((t.natural_metric[i] - want).norm(), 1e-12 * want.norm()) << i;
    EXPECT_NEAR(t.latex[i].volume, 1.3 * before.latex[i].volume, 1e-12 * before.latex[i].volume);
  }
}

TEST(Grow, UniformFactorScalesTheReleasedContinuumSheet) {
  // As the lattice's: a uniform growth by s has the sheet scaled by s as its stress-free shape.
  Membrane m = continuum_sheet();
  const double force_scale = m.sheet.material.youngs_modulus * m.sheet.material.thickness * 0.006;
  EXPECT_LT(uniform_growth_error(m, 1.25, force_scale), 1e-6 * 0.04);
}

}  // namespace
}  // namespace membra
