// The bundled example scenes, on coarser grids so the suite stays fast, reproduce the outcomes
// the paper reports; and the static and dynamic solvers agree where the answer is unique.
#include <gtest/gtest.h>

#include "membra/io/run.hpp"
#include "membra/io/scene.hpp"

namespace membra {
namespace {

const std::string kExamples = std::string(MEMBRA_SOURCE_DIR) + "/examples/";

RunResult run_example(const std::string& name, std::vector<std::string> sets) {
  return run_scene(load_scene(kExamples + name, sets));
}

TEST(Examples, ParallelStripsCurveTheWholeSheetPerpendicularStripsDoNot) {
  const std::vector<std::string> coarse = {"sheet.resolution=[21,21]"};
  const RunResult perpendicular = run_example("exp2_perpendicular.json", coarse);
  const RunResult parallel = run_example("exp3_parallel.json", coarse);
  ASSERT_TRUE(perpendicular.solve.converged) << perpendicular.solve.message;
  ASSERT_TRUE(parallel.solve.converged) << parallel.solve.message;
  const double size = 0.2;
  // Parallel strips: global curvature, height a sizeable fraction of the sheet (measured 70 mm
  // at 21 x 21 and 66 mm at 41 x 41).
  EXPECT_GT(parallel.shape.height, 0.15 * size);
  EXPECT_GT(parallel.shape.height, 3.0 * perpendicular.shape.height);
  // Perpendicular strips: the sheet stays nearly flat (below 1 % of its size).
  EXPECT_LT(perpendicular.shape.height, 0.01 * size);
}

TEST(Examples, StaticSolverAndDampedRk4ReachTheSameEquilibrium) {
  // exp1 (a sheet hanging from its corners) on an 11 x 11 grid: a stable, unique equilibrium.
  const std::vector<std::string> common = {"sheet.resolution=[11,11]", "simulation.tolerance=1e-9"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), common.begin(), common.end());
    return extra;
  };
  const RunResult fire = run_example("exp1_basic.json", with({"simulation.solver=static"}));
  const RunResult rk4 =
      run_example("exp1_basic.json", with({"simulation.solver=rk4", "simulation.steps=400000"}));
  ASSERT_TRUE(fire.solve.converged) << fire.solve.message;
  ASSERT_TRUE(rk4.solve.converged) << rk4.solve.message;
  const Points& a = fire.prepared.membrane.state.x;
  const Points& b = rk4.prepared.membrane.state.x;
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-4 * 0.2);
  EXPECT_GT(fire.shape.height, 0.01);  // it does sag (about 15 mm)
}

}  // namespace
}  // namespace membra
