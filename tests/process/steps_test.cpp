// The process layer on its own: each step's apply_<kind> returns the path the runner follows,
// following those paths by hand gives run_scene's form bit for bit, and a step that cannot be
// carried out names its field.
#include <gtest/gtest.h>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/process/path.hpp"
#include "membra/process/run.hpp"
#include "membra/process/steps.hpp"

namespace membra {
namespace {
using nlohmann::json;

// 100 x 100 mm latex on 11 x 11 particles, weightless: stretch, a resin strip, release.
Scene strip_scene(const json& pattern) {
  return parse_scene({{"name", "strip"},
                      {"sheet", {{"size", {100, 100}}, {"resolution", {11, 11}}}},
                      {"simulation", {{"G", 0.0}}},
                      {"protocol",
                       {{{"step", "stretch"}, {"lambda", {1.5, 1.0}}},
                        {{"step", "impregnate"}, {"pattern", pattern}},
                        {{"step", "release"}, {"increments", 3}}}}});
}

const json kStrip = {{"strip", {{"points", {{20, 50}, {130, 50}}}, {"width", 12}}}};

TEST(ProcessSteps, EachStepReturnsThePathTheRunnerFollows) {
  const Scene scene = strip_scene(kStrip);
  PreparedScene p = prepare_scene(scene);
  StepEffects stretch, resin, release;
  EXPECT_EQ(apply_step(p, scene.protocol[0], stretch).kind, Path::Kind::at_once);
  EXPECT_EQ(stretch.report.name, "stretch");
  EXPECT_EQ(apply_step(p, scene.protocol[1], resin).kind, Path::Kind::none);
  EXPECT_GT(resin.report.resin_springs, 10);
  const Path path = apply_step(p, scene.protocol[2], release);
  EXPECT_EQ(path.kind, Path::Kind::gradual);
  EXPECT_EQ(path.increments, 3);
  EXPECT_TRUE(p.membrane.releasing);
}

TEST(ProcessSteps, FollowingThePathsByHandIsRunScene) {
  const Scene scene = strip_scene(kStrip);
  const RunResult run = run_scene(scene);
  ASSERT_TRUE(run.solve.converged) << run.solve.message;
  PreparedScene p = prepare_scene(scene);
  std::vector<Frame> frames;
  FrameRecorder recorder{0, &frames};
  long iterations = 0;
  for (const ProtocolStep& step : scene.protocol) {
    StepEffects e;
    const Path path = apply_step(p, step, e);
    iterations +=
        follow_path(scene, p, p.membrane.state, e.report.name, path, {}, recorder).solve.iterations;
  }
  EXPECT_EQ(iterations, run.solve.iterations);
  EXPECT_EQ(p.membrane.state.x, run.prepared.membrane.state.x);  // bit for bit
  // The strip's mismatch bends the released sheet out of its plane.
  EXPECT_GT(run.shape.height, 1e-3);
}

TEST(ProcessSteps, AStepThatCannotBeCarriedOutNamesItsField) {
  // A strip between two rows of nodes covers no spring.
  const Scene scene = strip_scene({{"strip", {{"points", {{0, 55}, {150, 55}}}, {"width", 0.5}}}});
  try {
    (void)run_scene(scene);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/protocol/1/pattern");
  }
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

// Newton's increments adapt: capped at 30 iterations a solve, some of the hyperbola's ten
// release increments fail and are taken again in halves; the path still ends fully released
// (every latex spring back at its natural length, as a fixed-increment run leaves it).
TEST(ProcessPaths, NewtonHalvesAnIncrementThatFails) {
  const std::string file = std::string(MEMBRA_SOURCE_DIR) + "/examples/anticlastic_hyperbola.json";
  const std::vector<std::string> small = {"sheet.resolution=[15,15]", "simulation.solver=newton"};
  std::vector<std::string> capped = small;
  capped.push_back("simulation.max_iterations=30");
  const RunResult adaptive = run_scene(load_scene(file, capped));
  const RunResult fixed = run_scene(load_scene(file, small));
  EXPECT_EQ(fixed.solve.increments, 10);
  EXPECT_EQ(fixed.solve.increments_halved, 0);
  EXPECT_GE(adaptive.solve.increments_halved, 1);
  EXPECT_GT(adaptive.solve.increments, 10);
  const Springs& a = adaptive.prepared.membrane.sheet.model.springs;
  const Springs& b = fixed.prepared.membrane.sheet.model.springs;
  ASSERT_EQ(a.size(), b.size());
  for (int i = 0; i < a.size(); ++i) EXPECT_EQ(a.rest_length[i], b.rest_length[i]) << i;
}

}  // namespace
}  // namespace membra
