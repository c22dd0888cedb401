// Every solver notices a blow-up, stops, and says where and what to try.
#include <gtest/gtest.h>

#include "membra/solve/dynamics.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

// Two particles, one pinned, joined by a spring of negative stiffness: no equilibrium but the
// unstable one, and an energy that falls without bound as they part.
Model runaway() {
  Model m;
  m.add_particle(1.0, Vec3(0, 0, 0));
  m.add_particle(1.0, Vec3(1, 0, 0));
  m.pin(0);
  m.springs.add(0, 1, 0.5, -10.0, 0.0, SpringFamily::stretch);
  return m;
}

TEST(Divergence, StaticSolverStopsWhenTheSheetBlowsUp) {
  const Model m = runaway();
  State s = State::at_rest(m);
  StaticOptions o;
  o.max_iterations = 100000;
  const SolveReport r = solve_static(m, s, o);
  EXPECT_TRUE(r.diverged);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("diverged at iteration"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("try"), std::string::npos) << r.message;
  EXPECT_LT(r.iterations, o.max_iterations);
}

TEST(Divergence, TimeSteppingStopsWhenTheSheetBlowsUp) {
  const Model m = runaway();
  State s = State::at_rest(m);
  DynamicsOptions o;
  o.method = "rk4";
  o.dt = 0.01;
  o.steps = 1000000;
  const SolveReport r = run_dynamics(m, s, o);
  EXPECT_TRUE(r.diverged);
  EXPECT_NE(r.message.find("diverged at step"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("smaller time step"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace membra
