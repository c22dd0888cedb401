// Bilayer: the hinge kernel, Timoshenko's curvature, the hinges' moments against the plate
// energy's linear term, and a released strip that curls to the predicted curvature.
#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "membra/io/scene.hpp"
#include "membra/model/bilayer.hpp"
#include "membra/model/cut.hpp"
#include "membra/model/elements/hinge_kernel.hpp"
#include "membra/model/forces.hpp"
#include "membra/process/run.hpp"
#include "membra/solve/newton_solver.hpp"
#include "test_util.hpp"

namespace membra {
namespace {

TEST(HingeKernel, GradientMatchesFiniteDifferences) {
  const std::array<Vec3, 4> x = {Vec3(0, 0, 0), Vec3(1.0, 0.1, 0.05), Vec3(0.4, 0.9, 0.3),
                                 Vec3(0.6, -0.8, 0.2)};
  const HingeEval e = hinge_eval(x[0], x[1], x[2], x[3]);
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d) {
      auto xp = x, xm = x;
      const double h = 1e-6;
      xp[i][d] += h;
      xm[i][d] -= h;
      const double fd = (hinge_eval(xp[0], xp[1], xp[2], xp[3]).theta -
                         hinge_eval(xm[0], xm[1], xm[2], xm[3]).theta) /
                        (2 * h);
      EXPECT_NEAR(fd, e.grad[i][d], 1e-7) << i << "," << d;
    }
}

TEST(HingeKernel, AngleIsPositiveForAValleyAndNegativeForARidge) {
  // Edge along x; the left triangle rises by slope s with y, the right one too on its side.
  for (double phi : {0.1, 0.7, 1.5}) {
    const double s = std::tan(phi / 2);
    const Vec3 x0(0, 0, 0), x1(1, 0, 0), up(0.5, 1, s), down(0.5, -1, s);
    EXPECT_NEAR(hinge_eval(x0, x1, up, down).theta, phi, 1e-12);  // valley: a bowl towards +z
    const Vec3 up2(0.5, 1, -s), down2(0.5, -1, -s);
    EXPECT_NEAR(hinge_eval(x0, x1, up2, down2).theta, -phi, 1e-12);  // ridge: a dome
  }
  EXPECT_EQ(hinge_eval(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0)).theta, 0);
}

TEST(Bilayer, TimoshenkoMatchesItsClassicalLimits) {
  const Material base{"base", 2e6, 1e-3, 1000};
  // Equal layers: kappa = 3 eps / (2 h).
  EXPECT_NEAR(bilayer_curvature_per_strain(base, base), 1.5 / 2e-3, 1e-9);
  // A thin film (Stoney): kappa = 6 E_f t_f eps / (E_s t_s^2).
  Material film{"film", 5e6, 1e-7, 1000};
  EXPECT_NEAR(bilayer_curvature_per_strain(base, film) / (6 * 5e6 * 1e-7 / (2e6 * 1e-6)), 1.0,
              1e-3);
  // Latex with epoxy of the same thickness: about 4.7 1/m at the 1/3 misfit of lambda 1.5.
  EXPECT_NEAR(bilayer_curvature_per_strain(latex(), epoxy()) / 3.0, 4.76, 0.01);
  film.thickness = 0;
  EXPECT_THROW(bilayer_curvature_per_strain(base, film), std::invalid_argument);
}

Membrane stretched_sheet(int n, double size, double lx, double ly) {
  Membrane m = make_membrane(build_sheet({size, size, n, n}, SheetOptions{}));
  stretch_frame(m, lx, ly);
  return m;
}

struct HingeCase {
  double lx, ly, a, c;  // stretch, and the quadric z = (a x^2 + c y^2) / 2
};
class HingeMoments : public ::testing::TestWithParam<HingeCase> {};

// Summed over a regular triangulation, moment * theta integrates side * M : k with
// M = D [(1 - nu) k0 + nu tr(k0) I]: the linear term of the plate energy with spontaneous
// curvature k0 = T eps / h. Interior edges only, so (n - 1) / n of the area for each family.
TEST_P(HingeMoments, SumToThePlateEnergysLinearTerm) {
  const HingeCase q = GetParam();
  const int n = 31;
  const double size = 0.03;
  Membrane m = stretched_sheet(n, size, q.lx, q.ly);
  const auto all = make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  const Material resin = epoxy();
  impregnate(m, all, resin, +1, true);
  EXPECT_GT(m.sheet.model.hinges.size(), 0);
  EXPECT_EQ(set_energy(m.sheet.model.hinges, m.state.x), 0.0);  // no moment before the release
  begin_release(m);
  set_release_level(m, 0.0);
  Points x = m.state.x;
  for (int p = 0; p < x.cols(); ++p) {
    const double px = x(0, p) - 0.5 * size * q.lx, py = x(1, p) - 0.5 * size * q.ly;
    x(2, p) = 0.5 * (q.a * px * px + q.c * py * py);
  }
  const double k = bilayer_curvature_per_strain(latex(), resin);
  const double kx = k * (1 - 1 / q.lx), ky = k * (1 - 1 / q.ly);
  const double d = bending_stiffness(latex()) + bending_stiffness(resin), nu = 1.0 / 3.0;
  const double mxx = d * ((1 - nu) * kx + nu * (kx + ky)),
               myy = d * ((1 - nu) * ky + nu * (kx + ky));
  const double area = size * size * q.lx * q.ly * (n - 2.0) / (n - 1.0);
  const double expected = area * (mxx * q.a + myy * q.c);
  EXPECT_NEAR(set_energy(m.sheet.model.hinges, x) / expected, 1.0, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Cases, HingeMoments,
                         ::testing::Values(HingeCase{1.5, 1.5, 1.0, 1.0},
                                           HingeCase{1.5, 1.0, 1.0, 0.0},
                                           HingeCase{1.5, 1.0, 0.0, 1.0},
                                           HingeCase{1.2, 1.4, 2.0, -1.0}));

// A 100 x 10 mm strip, stretched 1.5x along x, resin over all of it on one face, released:
// the middle curls to Timoshenko's curvature, with the resin on the convex side.
double released_strip_curvature(int side) {
  Membrane m = make_membrane(build_sheet({0.1, 0.01, 41, 5}, SheetOptions{}));
  stretch_frame(m, 1.5, 1.0);
  const auto all = make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  impregnate(m, all, epoxy(), side, true);
  begin_release(m);
  // Newton: the 1700:1 resin/latex contrast makes relaxation slow on a strip this thin.
  NewtonOptions o;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  for (int k = 1; k <= 5; ++k) {
    set_release_level(m, 1.0 - k / 5.0);
    EXPECT_TRUE(solve_newton(m.sheet.model, m.state, o).converged) << k;
  }
  // Circle through three points of the middle row, in the plane of the bend.
  const GridSheet& g = m.sheet.grid;
  const Points& x = m.state.x;
  const Vec3 p0 = x.col(g.particle(10, 2)), p1 = x.col(g.particle(20, 2)),
             p2 = x.col(g.particle(30, 2));
  const double curvature = circle_curvature(p0, p1, p2);
  const double bulge = p1.z() - 0.5 * (p0.z() + p2.z());
  return bulge > 0 ? curvature : -curvature;
}

TEST(Bilayer, ReleasedStripCurlsToTimoshenkosCurvatureWithResinOnTheConvexSide) {
  const double expected = bilayer_curvature_per_strain(latex(), epoxy()) * (1.0 - 1.0 / 1.5);
  const double top = released_strip_curvature(+1);
  EXPECT_NEAR(top / expected, 1.0, 0.03);  // positive: bulges up, the top face convex
  EXPECT_NEAR(released_strip_curvature(-1) / -expected, 1.0, 0.03);
}

// The same strip coated in parts: coats given as (x from, x to, side), frame coordinates (mm; the
// stretched strip is 150 mm long), released through a scene as `membra run` would.
Membrane released_coated_strip(const std::vector<std::array<double, 3>>& coats, int nx = 41) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "name": "coated_strip", "sheet": {"size": [100, 10]},
    "simulation": {"solver": "newton", "G": 0},
    "protocol": [{"step": "stretch", "lambda": [1.5, 1.0]}]})");
  j["sheet"]["resolution"] = {nx, (nx - 1) / 10 + 1};  // square cells
  for (const auto& [from, to, side] : coats)
    j["protocol"].push_back(
        {{"step", "impregnate"},
         {"bilayer", true},
         {"resin_side", side > 0 ? "top" : "bottom"},
         {"pattern", {{"polygon", {{"points", {{from, -1}, {to, -1}, {to, 11}, {from, 11}}}}}}}});
  j["protocol"].push_back({{"step", "release"}, {"increments", 5}, {"perturbation", 0}});
  RunResult r = run_scene(parse_scene(j));
  EXPECT_TRUE(r.solve.converged);
  return std::move(r.prepared.membrane);
}

// Signed curvature of the middle row through columns i - 5, i, i + 5 (positive: bulges to +z).
double row_curvature(const Membrane& m, int i) {
  const GridSheet& g = m.sheet.grid;
  const Points& x = m.state.x;
  const int j = g.ny() / 2;
  const Vec3 p0 = x.col(g.particle(i - 5, j)), p1 = x.col(g.particle(i, j)),
             p2 = x.col(g.particle(i + 5, j));
  const double c = circle_curvature(p0, p1, p2);
  // Signed by the sheet's own top face (x cross y of the grid), not the world's z: a run's form
  // is turned into its reading pose, concave side up, whichever face it curls towards.
  const Vec3 top = (p2 - p0).cross(x.col(g.particle(i, j + 1)) - x.col(g.particle(i, j - 1)));
  return (p1 - 0.5 * (p0 + p2)).dot(top) > 0.0 ? c : -c;
}

// The largest turning angle between consecutive segments of the middle row: a crease shows as
// one angle many times the rest.
double largest_turn(const Membrane& m) {
  const GridSheet& g = m.sheet.grid;
  const Points& x = m.state.x;
  double largest = 0.0;
  for (int i = 1; i + 1 < g.nx(); ++i) {
    const int j = g.ny() / 2;
    const Vec3 a = x.col(g.particle(i, j)) - x.col(g.particle(i - 1, j));
    const Vec3 b = x.col(g.particle(i + 1, j)) - x.col(g.particle(i, j));
    largest = std::max(largest, std::atan2(a.cross(b).norm(), a.dot(b)));
  }
  return largest;
}

// Top coat on the left half, bottom coat on the right: an S, each half at Timoshenko's
// curvature with the coat on the convex side, and no crease where the coats meet (before the
// hinges across a coat's edge took the stiffness of the coat and latex in series, the edge
// carried the coat's moment against the latex's bending stiffness and folded by 1.9 rad).
TEST(Bilayer, CoatsOnOppositeFacesMakeAnSWithoutACrease) {
  const double expected = bilayer_curvature_per_strain(latex(), epoxy()) * (1.0 - 1.0 / 1.5);
  const Membrane s = released_coated_strip({{{-1, 75, +1}, {75, 151, -1}}});
  EXPECT_NEAR(row_curvature(s, 8) / expected, 1.0, 0.1);
  EXPECT_NEAR(row_curvature(s, 32) / -expected, 1.0, 0.1);
  // The evenly curled strip turns by kappa h = 0.018 rad per segment.
  EXPECT_LT(largest_turn(s), 3.0 * expected * 0.1 * 1.5 / 40);
}

// A coat on one half only: the coated half curls, the bare half stays straight, and the edge of
// the coat kinks by an angle that vanishes with the spacing (a discretization error: the last
// coated cell's moment meets the bare latex's bending stiffness). It folded by 1.9 rad before;
// measured 0.157 rad at 41 particles along, 0.058 at 81.
TEST(Bilayer, ACoatsEdgeKinkVanishesWithTheMesh) {
  const double expected = bilayer_curvature_per_strain(latex(), epoxy()) * (1.0 - 1.0 / 1.5);
  const Membrane coarse = released_coated_strip({{{-1, 75, +1}}});
  EXPECT_NEAR(row_curvature(coarse, 8) / expected, 1.0, 0.1);
  EXPECT_LT(std::abs(row_curvature(coarse, 32)), 0.05 * expected);
  const Membrane fine = released_coated_strip({{{-1, 75, +1}}}, 81);
  EXPECT_LT(largest_turn(coarse), 0.2);
  EXPECT_GT(largest_turn(coarse) / largest_turn(fine), 2.0);
}

// Two coats that meet edge to edge are one coat: the same form as their union (up to a rigid
// motion of the free strip), to the solver's tolerance.
TEST(Bilayer, CoatsThatMeetAreSeamless) {
  const Membrane two = released_coated_strip({{{-1, 75, +1}, {75, 151, +1}}});
  const Membrane one = released_coated_strip({{{-1, 151, +1}}});
  for (int i : {8, 20, 32}) EXPECT_NEAR(row_curvature(two, i) / row_curvature(one, i), 1.0, 1e-4);
  EXPECT_NEAR(largest_turn(two), largest_turn(one), 1e-6);
  // Overlapping coats count the overlap once.
  const Membrane overlapping = released_coated_strip({{{-1, 90, +1}, {60, 151, +1}}});
  for (int i : {8, 20, 32})
    EXPECT_NEAR(row_curvature(overlapping, i) / row_curvature(one, i), 1.0, 1e-4);
  for (double c : overlapping.sheet.model.hinges.coverage) EXPECT_LE(c, 1.0 + 1e-12);
}

// The scene key reaches the model: "bilayer": true bows the strip towards the resin face,
// without it the fully impregnated strip stays flat.
double scene_strip_bulge(const char* side, bool bilayer) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "name": "bilayer_strip",
    "sheet": {"size": [100, 10], "resolution": [21, 3]},
    "simulation": {"solver": "newton", "G": 0},
    "protocol": [
      {"step": "stretch", "lambda": [1.5, 1.0]},
      {"step": "impregnate", "pattern": {"polygon": {"points": [[-1, -1], [151, -1], [151, 11], [-1, 11]]}}},
      {"step": "release", "increments": 4, "perturbation": 0}
    ]})");
  j["protocol"][1]["resin_side"] = side;
  j["protocol"][1]["bilayer"] = bilayer;
  const RunResult r = run_scene(parse_scene(j));
  EXPECT_TRUE(r.solve.converged);
  const Points& x = r.prepared.membrane.state.x;
  const GridSheet& g = r.prepared.membrane.sheet.grid;
  // The sag of the middle over the chord, along the sheet's normal there (+z of the paper),
  // whatever rigid rotation the free strip took.
  const Vec3 mid = x.col(g.particle(10, 1));
  const Vec3 normal = (x.col(g.particle(11, 1)) - x.col(g.particle(9, 1)))
                          .cross(x.col(g.particle(10, 2)) - x.col(g.particle(10, 0)))
                          .normalized();
  return (mid - 0.5 * (x.col(g.particle(0, 1)) + x.col(g.particle(20, 1)))).dot(normal);
}

TEST(Bilayer, SceneKeyBowsTheStripTowardsTheResinFace) {
  // About 13 mm for a 150 mm arc of radius 210 mm.
  EXPECT_NEAR(scene_strip_bulge("top", true), 13e-3, 1.5e-3);
  EXPECT_NEAR(scene_strip_bulge("bottom", true), -13e-3, 1.5e-3);
  EXPECT_NEAR(scene_strip_bulge("top", false), 0.0, 1e-6);
}

// Cuts and holes take the hinges of the triangles they remove, and the rest keep their moments.
TEST(Bilayer, CutsAndHolesRemoveTheHingesTheyCross) {
  Membrane m = stretched_sheet(11, 0.05, 1.5, 1.5);
  const auto all = make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  impregnate(m, all, epoxy(), +1, true);
  begin_release(m);
  set_release_level(m, 0.0);
  auto consistent = [](const Membrane& mm) {
    const Hinges& h = mm.sheet.model.hinges;
    EXPECT_EQ(h.size(), static_cast<int>(h.full_moment.size()));
    for (int e = 0; e < h.size(); ++e) {
      for (int p : h.v[e]) EXPECT_LT(p, mm.sheet.model.num_particles());
      EXPECT_EQ(h.moment[e], h.full_moment[e]);  // released: the full moment
      EXPECT_NE(h.moment[e], 0.0);
    }
  };
  const int before = m.sheet.model.hinges.size();
  EXPECT_EQ(before, 3 * 10 * 10 - 2 * 10);  // interior edges of a 10 x 10 cell mesh
  consistent(m);
  cut_along(m, {{0.0, 0.0375}, {0.0375, 0.0375}});  // half way across, between grid lines
  const int after_cut = m.sheet.model.hinges.size();
  EXPECT_LT(after_cut, before);
  consistent(m);
  punch_hole(m, *make_ellipse({0.05, 0.02}, 0.012, 0.012, 0.0));
  EXPECT_LT(m.sheet.model.hinges.size(), after_cut);
  consistent(m);
}

}  // namespace
}  // namespace membra
