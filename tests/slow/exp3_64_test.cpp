// Slow acceptance tests (label "slow"; on the 2-core machine several minutes each, which
// scripts/test runs side by side): the examples' solver (newton) converges on exp3 at 64 x 64 with
// a resin/latex stiffness ratio of 2000; exp2 and exp3 as shipped (41 x 41, the grid exp2's
// creases need) give local folds and global curvature.
// Run alone with: ctest --test-dir build -L slow
#include <cmath>

#include <gtest/gtest.h>

#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

TEST(SlowExamples, Exp3ConvergesAt64x64WithStiffnessRatio2000) {
  // Epoxy E = 3000 MPa against latex 1.5 MPa.
  const Scene scene = load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json",
                                 {"sheet.resolution=[64,64]", "materials.epoxy.E=3000"});
  ASSERT_DOUBLE_EQ(scene.protocol[1].as<ImpregnateStep>()->resin.youngs_modulus /
                       scene.sheet.material.youngs_modulus,
                   2000.0);
  const RunResult r = run_scene(scene);
  EXPECT_TRUE(r.solve.converged) << r.solve.message;
  EXPECT_LE(r.solve.residual_relative, 1e-6);
  EXPECT_GT(r.shape.height, 0.15 * 0.2);  // still the global curvature of exp3 (67 mm measured)
}

TEST(SlowExamples, PerpendicularStripsCreaseLocallyParallelStripsCurveTheSheet) {
  const std::string dir = std::string(MEMBRA_SOURCE_DIR) + "/examples/";
  // exp2 has two stable forms at 41 x 41 (docs/forms.md): the paper's creases running the whole
  // sheet along the stretch, which the static solver's damped path reaches (33.4 mJ), and a lower
  // egg-crate of creases broken at every strip, which Newton reaches (31.9 mJ). The test is of
  // the paper's specimen, so it takes the damped path.
  const RunResult exp2 =
      run_scene(load_scene(dir + "exp2_perpendicular.json", {"simulation.solver=static"}));
  const RunResult exp3 = run_scene(load_scene(dir + "exp3_parallel.json", {}));
  ASSERT_TRUE(exp2.solve.converged) << exp2.solve.message;
  ASSERT_TRUE(exp3.solve.converged) << exp3.solve.message;
  const double size = 0.2;
  // exp2: creases between the strips (measured fold rms 1.4 mm at 41 x 41, 1.1 at 51 x 51) on a
  // sheet that stays nearly flat at the scale of the sheet (global height 6.9 mm, 7.7 at 51).
  EXPECT_GT(exp2.shape.fold_rms, 0.5e-3);
  EXPECT_LT(exp2.shape.global_height, 0.05 * size);
  EXPECT_LT(exp2.shape.height, 0.1 * size);
  // The creases run along the stretch: heights vary across (along y) far more than along x.
  const Points& x = exp2.prepared.membrane.state.x;
  const GridSheet& g = exp2.prepared.membrane.sheet.grid;
  double along = 0.0, across = 0.0;
  for (int j = 1; j + 1 < g.ny(); ++j)
    for (int i = 1; i + 1 < g.nx(); ++i) {
      const double z = x(2, g.particle(i, j));
      along += std::abs(x(2, g.particle(i + 1, j)) - 2 * z + x(2, g.particle(i - 1, j)));
      across += std::abs(x(2, g.particle(i, j + 1)) - 2 * z + x(2, g.particle(i, j - 1)));
    }
  EXPECT_GT(across, 2.0 * along);
  // exp3: the whole sheet curves (rolls up), at least 3x exp2's height.
  EXPECT_GT(exp3.shape.height, 3.0 * exp2.shape.height);
  EXPECT_GT(exp3.shape.global_height, 3.0 * exp2.shape.global_height);
}

}  // namespace
}  // namespace membra
