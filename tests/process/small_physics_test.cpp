// The physics code on small grids, so that the sanitized build (scripts/check-sanitized: ASan +
// UBSan, 50-100x slower) checks it as well as the parsers: the forward examples, every step
// kind and both equilibrium solvers (below), each run twice, and a dynamic (rk4) sagging sheet.
// What is checked is that the code runs cleanly (no sanitizer report) to a finite end state,
// the same twice; the numbers are
// checked at full size by the tests the sanitized run leaves out (Examples, Kirsch, Determinism,
// HangingChain, CompressedStrip); their set-ups run sanitized, scaled down, in small_setups_test.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

const std::string kExamples = std::string(MEMBRA_SOURCE_DIR) + "/examples/";

struct SmallRun {
  const char* example;
  const char* solver;
};

class SmallPhysics : public ::testing::TestWithParam<SmallRun> {};

// Each example on a 9 x 9 grid (its sheets are square), its solves capped at 20 000 iterations
// (the static solver on a coarse bilayer could otherwise crawl for minutes under ASan).
TEST_P(SmallPhysics, ExampleRunsToAFiniteEndState) {
  const SmallRun c = GetParam();
  const Scene scene =
      load_scene(kExamples + c.example,
                 {"sheet.resolution=[9,9]", std::string("simulation.solver=") + c.solver,
                  "simulation.max_iterations=20000", "simulation.max_seconds=600"});
  const RunResult r = run_scene(scene);
  EXPECT_FALSE(r.solve.diverged) << r.solve.message;
  EXPECT_TRUE(r.prepared.membrane.state.x.allFinite());
  EXPECT_TRUE(std::isfinite(r.curvature.total));
  EXPECT_TRUE(std::isfinite(r.stress.max_stress));
  // Repeated: the same bits (the determinism test's claim, at this size).
  const RunResult again = run_scene(scene);
  EXPECT_EQ(r.prepared.membrane.state.x, again.prepared.membrane.state.x);
}

// Every step kind and both equilibrium solvers, each example once: release of strips (exp3),
// grow (exp4, exp5), curvature map (exp6), cut and hole (exp7), the bilayer's hinges, union and
// hyperbola patterns.
std::vector<SmallRun> small_runs() {
  // The static solver where it is quick on a coarse sheet (grow, curvature map); under ASan its
  // thousands of iterations on the strip and ellipse releases took two minutes each.
  return {{"exp3_parallel.json", "newton"},      {"exp4_intrinsic_sin2.json", "static"},
          {"exp5_shrink.json", "newton"},        {"exp6_curvature_map.json", "static"},
          {"exp7_cut.json", "newton"},           {"bilayer_roll.json", "newton"},
          {"synclastic_ellipse.json", "newton"}, {"anticlastic_hyperbola.json", "newton"}};
}

INSTANTIATE_TEST_SUITE_P(Examples9, SmallPhysics, ::testing::ValuesIn(small_runs()),
                         [](const ::testing::TestParamInfo<SmallRun>& run) {
                           std::string name =
                               std::string(run.param.example) + "_" + run.param.solver;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

// The paper's dynamic solver (rk4 with damping) on a small sheet sagging under gravity: the
// time-stepping code path the examples' equilibrium solvers do not take.
TEST(SmallPhysicsDynamic, Rk4SagsUnderGravity) {
  const Scene scene = load_scene(kExamples + "exp1_basic.json",
                                 {"sheet.resolution=[7,7]", "simulation.solver=rk4",
                                  "simulation.steps=4000", "simulation.max_seconds=600"});
  const RunResult r = run_scene(scene);
  EXPECT_FALSE(r.solve.diverged) << r.solve.message;
  EXPECT_TRUE(r.prepared.membrane.state.x.allFinite());
  EXPECT_LT(r.prepared.membrane.state.x.row(2).minCoeff(), 0.0);  // it sags
}

}  // namespace
}  // namespace membra
