// simulation.max_seconds: a wall-time budget for the whole run, whatever the solver.
#include <gtest/gtest.h>

#include <string>

#include "membra/core/stopwatch.hpp"
#include "membra/io/scene.hpp"
#include "membra/output/report.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

const std::string kExp3 = std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json";

class Budget : public ::testing::TestWithParam<const char*> {};

TEST_P(Budget, ARunStopsAtItsWallTimeBudgetAndSaysSo) {
  // exp3 at 41 x 41 takes a minute or more with either equilibrium solver.
  const Scene scene = load_scene(
      kExp3, {"simulation.max_seconds=1", std::string("simulation.solver=") + GetParam()});
  const Stopwatch clock;
  const RunResult r = run_scene(scene);
  // The budget is checked at every convergence check; the end-of-run summary (a stability check
  // of a 41 x 41 sheet) comes on top, and ctest runs a browser or a sweep beside this test: a
  // loose bound, still far below the minute the run would take.
  EXPECT_LT(clock.seconds(), 30.0);
  EXPECT_TRUE(r.out_of_time);
  EXPECT_FALSE(r.solve.converged);
  EXPECT_NE(r.solve.message.find("simulation.max_seconds = 1"), std::string::npos)
      << r.solve.message;
  const auto report = make_report(scene, r);
  EXPECT_EQ(report["out_of_time"], true);
  EXPECT_EQ(report["max_seconds"], 1.0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, Budget, ::testing::Values("static", "newton"));

TEST(BudgetUnused, ARunWithinItsBudgetIsTheSame) {
  const std::vector<std::string> small = {"sheet.resolution=[11,11]", "simulation.solver=newton"};
  std::vector<std::string> budget = small;
  budget.push_back("simulation.max_seconds=600");
  const RunResult a = run_scene(load_scene(kExp3, small));
  const RunResult b = run_scene(load_scene(kExp3, budget));
  EXPECT_FALSE(b.out_of_time);
  EXPECT_TRUE(b.solve.converged);
  EXPECT_EQ(a.prepared.membrane.state.x, b.prepared.membrane.state.x);
}

}  // namespace
}  // namespace membra
