// Slow acceptance test (label "slow", about 8 minutes on the 2-core machine): the default
// static solver converges on exp3 at 64 x 64 with a resin/latex stiffness ratio of 2000.
// Run alone with: ctest --test-dir build -L slow
#include <gtest/gtest.h>

#include "membra/io/run.hpp"
#include "membra/io/scene.hpp"

namespace membra {
namespace {

TEST(SlowExamples, Exp3ConvergesAt64x64WithStiffnessRatio2000) {
  // Epoxy E = 3000 MPa against latex 1.5 MPa.
  const Scene scene = load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json",
                                 {"sheet.resolution=[64,64]", "materials.epoxy.E=3000"});
  ASSERT_DOUBLE_EQ(scene.protocol[1].resin.youngs_modulus / scene.sheet.material.youngs_modulus,
                   2000.0);
  const RunResult r = run_scene(scene);
  EXPECT_TRUE(r.solve.converged) << r.solve.message;
  EXPECT_LE(r.solve.residual_relative, 1e-6);
  EXPECT_GT(r.shape.height, 0.15 * 0.2);  // still the global curvature of exp3 (67 mm measured)
}

}  // namespace
}  // namespace membra
