// Multilevel release (docs/solver.md): which grids a run passes through, and that the form a
// coarser grid hands on settles on the finer one where the physics has one answer — a coat on
// one face rolls the sheet to Timoshenko's radius, from a coarser grid as from the path.
#include "membra/process/multilevel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/model/bilayer.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

using Grids = std::vector<std::pair<int, int>>;

Scene example(const std::string& name, std::vector<std::string> sets) {
  return load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/" + name, sets);
}

TEST(Multilevel, HalvesTheGridDownToTheCoarsest) {
  EXPECT_EQ(multilevel_grids(example("exp3_parallel.json",
                                     {"sheet.resolution=[64,64]", "simulation.multilevel=32"})),
            (Grids{{32, 32}, {64, 64}}));
  // A sheet twice as long as wide keeps square cells on every grid.
  EXPECT_EQ(multilevel_grids(example(
                "exp3_parallel.json",
                {"sheet.size=[200,100]", "sheet.resolution=[129,65]", "simulation.multilevel=32"})),
            (Grids{{33, 17}, {65, 33}, {129, 65}}));
  // Off, too small to halve above the coarsest, or a solver that follows no path: one grid.
  EXPECT_EQ(multilevel_grids(example("exp3_parallel.json", {"sheet.resolution=[64,64]"})),
            (Grids{{64, 64}}));
  EXPECT_EQ(multilevel_grids(example("exp3_parallel.json",
                                     {"sheet.resolution=[61,61]", "simulation.multilevel=32"})),
            (Grids{{61, 61}}));
}

// The tip after a long run: only without levels, from 64 nodes up, after 30 s, and where a
// path could be followed on coarser grids.
TEST(Multilevel, ALongFineRunWithoutLevelsGetsATip) {
  const Scene fine = example("synclastic_ellipse.json", {"sheet.resolution=[64,64]"});
  const std::string tip = multilevel_hint(fine, 88.0);
  EXPECT_NE(tip.find("64x64 run took 88 s"), std::string::npos) << tip;
  EXPECT_NE(tip.find("--set simulation.multilevel=16"), std::string::npos) << tip;
  EXPECT_EQ(multilevel_hint(fine, 20.0), "");  // quick enough
  EXPECT_EQ(multilevel_hint(example("synclastic_ellipse.json",
                                    {"sheet.resolution=[64,64]", "simulation.multilevel=32"}),
                            88.0),
            "");  // levels already
  EXPECT_EQ(multilevel_hint(example("synclastic_ellipse.json", {"sheet.resolution=[41,41]"}), 88.0),
            "");  // too coarse to gain
  EXPECT_EQ(multilevel_hint(example("synclastic_ellipse.json",
                                    {"sheet.resolution=[64,64]", "simulation.solver=rk4"}),
                            88.0),
            "");  // no path to follow
}

TEST(Multilevel, RefusesWhatCannotWork) {
  EXPECT_THROW(example("exp3_parallel.json", {"simulation.multilevel=3"}), InputError);
  EXPECT_THROW(example("exp3_parallel.json", {"simulation.multilevel=-1"}), InputError);
  EXPECT_THROW(example("exp3_parallel.json", {"simulation.solver=rk4", "simulation.multilevel=9"}),
               InputError);
}

// bilayer_roll: the coat keeps the 300 mm frame length along x and curls the sheet into an arc
// of Timoshenko's radius (the sagitta 51 mm). Released at 21² from an 11² release, the roll must
// be that arc within 5 % and the plain 21² release's within 1 %.
TEST(Multilevel, ACoarserGridsRollSettlesToTimoshenkosRadius) {
  const std::vector<std::string> sets = {"sheet.resolution=[21,21]"};
  const RunResult plain = run_scene(example("bilayer_roll.json", sets));
  const RunResult r =
      run_scene(example("bilayer_roll.json", {sets[0], "simulation.multilevel=11"}));
  ASSERT_TRUE(plain.solve.converged && r.solve.converged) << r.solve.message;
  ASSERT_EQ(r.levels.size(), 2u);
  EXPECT_EQ(r.levels[0].nx, 11);
  EXPECT_TRUE(r.levels[1].from_coarser);
  EXPECT_TRUE(r.stability.stable);
  const double kappa = bilayer_curvature_per_strain(latex(), epoxy()) * (1.0 - 1.0 / 1.5);
  const double radius = 1.0 / kappa, arc = 0.3;
  const double sagitta = radius * (1.0 - std::cos(0.5 * arc / radius));
  EXPECT_NEAR(r.shape.height / sagitta, 1.0, 0.05);
  EXPECT_NEAR(r.shape.height / plain.shape.height, 1.0, 0.01);
  // The finer grid only settles the form: far fewer iterations than the coarse path took.
  EXPECT_LT(r.levels[1].solve.iterations, r.levels[0].solve.iterations);
}

// exp3 at 15² from 8²: the coarse rolls do not settle on the finer grid within a solve's
// iterations (measured: 500, far from the tolerance), so that grid follows its own path — and
// then the answer is exactly the run without levels.
TEST(Multilevel, AFormThatDoesNotSettleFallsBackToThePath) {
  const std::vector<std::string> sets = {"sheet.resolution=[15,15]"};
  const RunResult plain = run_scene(example("exp3_parallel.json", sets));
  const RunResult r =
      run_scene(example("exp3_parallel.json", {sets[0], "simulation.multilevel=8"}));
  ASSERT_EQ(r.levels.size(), 3u);
  EXPECT_TRUE(r.levels[1].from_coarser);
  EXPECT_FALSE(r.levels[1].solve.converged);
  EXPECT_FALSE(r.levels[2].from_coarser);
  EXPECT_TRUE(r.solve.converged);
  const Points& a = plain.prepared.membrane.state.x;
  const Points& b = r.prepared.membrane.state.x;
  ASSERT_EQ(a.cols(), b.cols());
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Multilevel, OnTheContinuumDoublesTheMeshDownToTheCoarsest) {
  // exp5: a 200 mm sheet, default max_edge 10 mm (its smaller side / 20), 4 elements across.
  const std::vector<GridLevel> levels = multilevel_meshes(
      example("exp5_shrink.json", {"model=continuum", "simulation.multilevel=5"}));
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_DOUBLE_EQ(levels[0].max_edge, 0.04);
  EXPECT_DOUBLE_EQ(levels[1].max_edge, 0.02);
  EXPECT_DOUBLE_EQ(levels[2].max_edge, 0.01);
  EXPECT_EQ(levels[0].elements_across, 2);
  EXPECT_EQ(levels[2].elements_across, 4);
  EXPECT_EQ(multilevel_meshes(example("exp5_shrink.json", {"model=continuum"})).size(), 1u);
  // A cut as the last step is solved at once and changes the particles: no levels.
  EXPECT_EQ(
      multilevel_meshes(example("exp7_cut.json", {"model=continuum", "simulation.multilevel=5"}))
          .size(),
      1u);
  EXPECT_EQ(multilevel_grids(example("exp7_cut.json", {"simulation.multilevel=5"})).size(), 1u);
  // elements_across is halved to 2 at the least, never raised.
  const std::vector<GridLevel> one_across =
      multilevel_meshes(example("exp5_shrink.json", {"model=continuum", "simulation.multilevel=5",
                                                     "sheet.mesh.elements_across=1"}));
  ASSERT_EQ(one_across.size(), 3u);
  EXPECT_EQ(one_across[0].elements_across, 1);
  // The lattice's grids are not the continuum's levels, and the reverse.
  EXPECT_EQ(
      multilevel_grids(example("exp5_shrink.json", {"model=continuum", "simulation.multilevel=5"}))
          .size(),
      1u);
}

// bilayer_roll on the continuum's 20 mm mesh, released from a 40 mm mesh's roll: the same arc as
// its own path's within 1 %, settled in fewer iterations than the coarse path took.
TEST(Multilevel, OnTheContinuumACoarserMeshsRollSettlesAsThePathsDoes) {
  const std::vector<std::string> sets = {"model=continuum", "sheet.mesh.max_edge=20"};
  const RunResult plain = run_scene(example("bilayer_roll.json", sets));
  const RunResult r =
      run_scene(example("bilayer_roll.json", {sets[0], sets[1], "simulation.multilevel=5"}));
  ASSERT_TRUE(plain.solve.converged && r.solve.converged) << r.solve.message;
  ASSERT_EQ(r.levels.size(), 2u);  // 200 mm: 5 edges of 40 mm, not 2.5 of 80 mm
  EXPECT_DOUBLE_EQ(r.levels[0].max_edge, 0.04);
  EXPECT_GT(r.levels[1].vertices, r.levels[0].vertices);
  EXPECT_TRUE(r.levels[1].from_coarser);
  EXPECT_TRUE(r.stability.stable);
  std::printf(
      "bilayer_roll, continuum, 20 mm from 40 mm: %.2f mm high (path %.2f mm), %ld + %ld "
      "iterations (path %ld)\n",
      r.shape.height * 1e3, plain.shape.height * 1e3, r.levels[0].solve.iterations,
      r.levels[1].solve.iterations, plain.solve.iterations);
  EXPECT_NEAR(r.shape.height / plain.shape.height, 1.0, 0.01);
  EXPECT_LT(r.levels[1].solve.iterations, r.levels[0].solve.iterations);
}

// The hyperbola's coarser mesh (20 mm, 2 elements across) is refused by the mesher: a sliver
// where the pattern meets the sheet's edge, which the 10 mm mesh's sampling of the boundaries
// does not find. The run then follows the scene's own path (here out of its 3 s budget) and
// says why, instead of failing.
TEST(Multilevel, OnTheContinuumAMeshTheMesherRefusesFallsBackToThePath) {
  const RunResult r = run_scene(
      example("anticlastic_hyperbola.json",
              {"model=continuum", "simulation.multilevel=10", "simulation.max_seconds=3"}));
  EXPECT_TRUE(r.levels.empty());
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("max_edge 20 mm"), std::string::npos) << r.warnings.front();
  EXPECT_NE(r.warnings.front().find("narrower than the mesher resolves"), std::string::npos);
  EXPECT_GT(r.prepared.membrane.sheet.mesh.vertices, 2000);  // the scene's own 10 mm mesh
}

}  // namespace
}  // namespace membra
