// Holes and slits on the continuum sheet (continuum_hole.hpp, continuum_slit.hpp): the mesh is
// made with their outlines as edge paths; the hole removes what lies inside, the slit gives each
// particle along it one copy per side. Checked by the mesh's topology (Euler's characteristic),
// Gauss-Bonnet to round-off on the holed, slit sheet however it is bent, and the slit opening
// under tension across it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <utility>

#include "membra/measure/curvature.hpp"
#include "membra/model/continuum_hole.hpp"
#include "membra/model/continuum_sheet.hpp"
#include "membra/model/continuum_slit.hpp"
#include "membra/model/pattern_boundary.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace continuum_cut_test {
namespace {

// A 100 x 60 mm sheet, a hole of 10 mm radius at (30, 30) mm and a slit from (60, 20) to
// (80, 40) mm, both inside it and apart, meshed in and cut.
struct Cut {
  Membrane m;
  int removed = 0, opened = 0, particles_before = 0;
};

const std::vector<Vec2> kSlit{Vec2(0.06, 0.02), Vec2(0.08, 0.04)};

Cut holed_slit_sheet(double max_edge) {
  ContinuumSpec spec;
  spec.width = 0.1, spec.height = 0.06;
  spec.mesh.max_edge = max_edge;
  const PatternPtr hole = make_ellipse(Vec2(0.03, 0.03), 0.01, 0.01, 0.0);
  BoundaryOptions o;
  o.tolerance = spec.mesh.tolerance;
  spec.features = pattern_boundaries(*hole, Box2{Vec2::Zero(), Vec2(0.1, 0.06)}, o);
  spec.slits = {kSlit};
  Cut c{make_membrane(build_continuum_sheet(spec))};
  c.particles_before = c.m.sheet.model.num_particles();
  c.removed = punch_continuum_hole(c.m, *hole);
  c.opened = cut_continuum_slit(c.m, kSlit);
  return c;
}

// Euler's characteristic V - E + F of the sheet's triangles.
int euler_characteristic(const Sheet& s) {
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : s.triangles)
    for (int e = 0; e < 3; ++e)
      edges.insert({std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])});
  return s.model.num_particles() - static_cast<int>(edges.size()) +
         static_cast<int>(s.triangles.size());
}

TEST(ContinuumCut, ASlitGivesEachParticleAlongItOneCopyAndLeavesItsTipsWhole) {
  const Cut c = holed_slit_sheet(0.005);
  EXPECT_GT(c.removed, 0);
  ASSERT_GT(c.opened, 3);
  const Sheet& s = c.m.sheet;
  // A slit of `opened` edges has opened + 1 particles; the two tips inside stay single.
  EXPECT_EQ(s.model.num_particles(), c.particles_before - c.removed + c.opened - 1);
  EXPECT_EQ(s.mesh.vertices, s.model.num_particles());
  // A sheet with a hole and a slit: three boundary loops, so chi = 2 - 3.
  EXPECT_EQ(euler_characteristic(s), -1);
  // Every element set follows: the membrane's and the shell's corners are the sheet's.
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& m = s.model.membrane_triangles.v[t];
    const auto& b = s.model.shell_triangles.v[t];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m[static_cast<size_t>(k)], s.triangles[t][k]);
      EXPECT_EQ(b[static_cast<size_t>(k)], s.triangles[t][k]);
    }
  }
  // Every particle, the copies among them, has a third of its triangles' mass; all add up to
  // the sheet's, less the hole.
  std::vector<double> share(static_cast<size_t>(s.model.num_particles()), 0.0);
  const Points& ref = s.model.reference;
  const double density = s.material.thickness * s.material.density;
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k)
      share[static_cast<size_t>(t[k])] +=
          density / 6.0 *
          (ref.col(t[1]) - ref.col(t[0])).cross(ref.col(t[2]) - ref.col(t[0])).norm();
  for (int p = 0; p < s.model.num_particles(); ++p) {
    ASSERT_GT(s.model.mass[static_cast<size_t>(p)], 0.0) << p;
    EXPECT_NEAR(s.model.mass[static_cast<size_t>(p)], share[static_cast<size_t>(p)], 1e-15) << p;
  }
  double mass = 0.0;
  for (double q : s.model.mass) mass += q;
  const double area = 0.1 * 0.06 - std::numbers::pi * 1e-4;
  EXPECT_NEAR(mass, area * s.material.thickness * s.material.density, 1e-3 * mass);
}

// A slit whose tip lies on a square hole's edge, the slit cut first: once the hole is cut the
// tip joins the slit's two lips only at a corner, and it is split too, so the slit opens into the
// hole whatever the order of the cuts: two boundary loops (chi 0), not a pinched one.
TEST(ContinuumCut, ASlitsTipOnAHolesEdgeOpensIntoTheHole) {
  ContinuumSpec spec;
  spec.width = 0.1, spec.height = 0.06;
  spec.mesh.max_edge = 0.005;
  const PatternPtr hole =
      make_polygon({Vec2(0.07, 0.025), Vec2(0.08, 0.025), Vec2(0.08, 0.035), Vec2(0.07, 0.035)});
  BoundaryOptions o;
  o.tolerance = spec.mesh.tolerance;
  spec.features = pattern_boundaries(*hole, Box2{Vec2::Zero(), Vec2(0.1, 0.06)}, o);
  const std::vector<Vec2> slit{Vec2(0.04, 0.03), Vec2(0.07, 0.03)};
  spec.slits = {slit};
  Membrane m = make_membrane(build_continuum_sheet(spec));
  const int opened = cut_continuum_slit(m, slit);
  ASSERT_GT(opened, 3);
  const int before = m.sheet.model.num_particles();
  EXPECT_GT(punch_continuum_hole(m, *hole), 0);
  EXPECT_EQ(euler_characteristic(m.sheet), 0);
  // The tip is two particles now, at one paper position.
  int at_tip = 0;
  for (int p = 0; p < m.sheet.model.num_particles(); ++p)
    at_tip += (m.sheet.model.reference.col(p).head<2>() - Vec2(0.07, 0.03)).norm() < 1e-9;
  EXPECT_EQ(at_tip, 2);
  EXPECT_LT(m.sheet.model.num_particles(), before);
}

TEST(ContinuumCut, GaussBonnetHoldsToRoundOffOnTheHoledSlitSheetHoweverItBends) {
  Cut c = holed_slit_sheet(0.005);
  Points& x = c.m.state.x;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  for (int p = 0; p < x.cols(); ++p) {
    const double u = x(0, p), v = x(1, p);
    x(2, p) = 0.01 * std::sin(40.0 * u) * std::cos(60.0 * v) + 0.02 * u * v / 0.006;
    x(0, p) += jitter(rng), x(1, p) += jitter(rng);
  }
  const GaussianCurvature k = gaussian_curvature(x, c.m.sheet.triangles);
  EXPECT_NEAR(k.total + k.boundary, 2.0 * std::numbers::pi * euler_characteristic(c.m.sheet), 1e-9);
  EXPECT_GT(std::abs(k.total), 0.1);  // it does bend
}

TEST(ContinuumCut, TheSlitOpensUnderTensionAcrossIt) {
  Cut c = holed_slit_sheet(0.005);
  stretch_frame(c.m, 1.0, 1.05, FrameEdges{false, false, true, true});
  NewtonOptions n;
  n.force_scale = c.m.sheet.stiffness.stretch * c.m.sheet.mesh.mean_edge;
  n.tolerance = 1e-8;
  n.in_plane = true;
  const SolveReport r = solve_newton(c.m.sheet.model, c.m.state, n);
  ASSERT_TRUE(r.converged) << r.message;
  // The slit's lips: pairs of particles at one paper position. The widest gap lies mid-slit.
  std::map<std::pair<double, double>, std::vector<int>> at;
  const Points& ref = c.m.sheet.model.reference;
  for (int p = 0; p < ref.cols(); ++p) at[{ref(0, p), ref(1, p)}].push_back(p);
  double widest = 0.0;
  Vec2 where = Vec2::Zero();
  for (const auto& [paper, ps] : at) {
    if (ps.size() != 2) continue;
    const double gap = (c.m.state.x.col(ps[0]) - c.m.state.x.col(ps[1])).norm();
    if (gap > widest) widest = gap, where = Vec2(paper.first, paper.second);
  }
  EXPECT_GT(widest, 0.5e-3);  // m: a 28 mm slit at 45 degrees in a 5 % stretch
  EXPECT_LT((where - Vec2(0.07, 0.03)).norm(), 0.006);
}

}  // namespace
}  // namespace continuum_cut_test
}  // namespace membra
