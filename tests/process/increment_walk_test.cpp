// The one walk along a path's increments (process/increment_walk.hpp) that follow_path and the
// viewer share: positions, tolerances, halving, growth and the secant predictor.
#include "membra/process/increment_walk.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace membra {
namespace {

// A gradual path of n increments that records every t it is set to.
Path recording_path(int n, std::vector<double>& ts) {
  Path p;
  p.kind = Path::Kind::gradual;
  p.increments = n;
  p.set = [&ts](double t) { ts.push_back(t); };
  return p;
}

SimulationSpec tolerances() {
  SimulationSpec sim;
  sim.tolerance = 1e-6;
  sim.path_tolerance = 1e-3;
  return sim;
}

// First order (the viewer's relaxation, FIRE): the scene's increments k/n, each to the path
// tolerance but the last, which is solved in full; no halving.
TEST(IncrementWalk, FirstOrderTakesTheScenesIncrements) {
  std::vector<double> ts;
  IncrementWalk walk(recording_path(4, ts), tolerances(), false);
  Points x = Points::Zero(3, 2);
  std::vector<double> tol;
  while (!walk.done()) {
    tol.push_back(walk.begin(x));
    EXPECT_FALSE(walk.halve(x));
    walk.accept(x, 100);
  }
  EXPECT_EQ(ts, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(tol, (std::vector<double>{1e-3, 1e-3, 1e-3, 1e-6}));
  EXPECT_TRUE(x.isZero());  // no predictor
}

// Second order (Newton): a failed increment is undone and halved, down to an eighth; easy ones
// let the length grow back; labels name the scene's increments or the per cent between them.
TEST(IncrementWalk, SecondOrderHalvesAndGrowsBack) {
  std::vector<double> ts;
  IncrementWalk walk(recording_path(2, ts), tolerances(), true);
  Points x = Points::Zero(3, 1);
  walk.begin(x);
  EXPECT_EQ(walk.stage("release"), "release 1/2");
  x.setConstant(7.0);  // a failed solve wandered off
  ASSERT_TRUE(walk.halve(x));
  EXPECT_TRUE(x.isZero());  // back at the increment's start
  walk.begin(x);
  EXPECT_DOUBLE_EQ(walk.t(), 0.25);
  EXPECT_EQ(walk.stage("release"), "release 25%");
  ASSERT_TRUE(walk.halve(x));
  walk.begin(x);
  EXPECT_DOUBLE_EQ(walk.t(), 0.125);
  ASSERT_TRUE(walk.halve(x));
  walk.begin(x);
  EXPECT_DOUBLE_EQ(walk.t(), 0.0625);
  EXPECT_FALSE(walk.halve(x));  // an eighth of an increment is the least
  walk.accept(x, 100);          // hard: the length stays an eighth
  walk.begin(x);
  EXPECT_DOUBLE_EQ(walk.t(), 0.125);
  walk.accept(x, 5);  // easy: it doubles
  walk.begin(x);
  EXPECT_DOUBLE_EQ(walk.t(), 0.25);
  EXPECT_EQ(walk.tolerance(), 1e-3);  // not the last
}

// The secant predictor: each increment starts from the last one's motion, scaled to its length.
TEST(IncrementWalk, ThePredictorScalesTheLastMotion) {
  std::vector<double> ts;
  IncrementWalk walk(recording_path(4, ts), tolerances(), true);
  Points x = Points::Zero(3, 1);
  walk.begin(x);
  x(2, 0) = 0.8;  // the first increment's solve moved it by 0.8
  walk.accept(x, 100);
  walk.begin(x);
  EXPECT_DOUBLE_EQ(x(2, 0), 1.6);  // predicted: the same motion again
  ASSERT_TRUE(walk.halve(x));
  EXPECT_DOUBLE_EQ(x(2, 0), 0.8);
  walk.begin(x);
  EXPECT_DOUBLE_EQ(x(2, 0), 1.2);  // half the length, half the motion
}

TEST(IncrementWalk, APathThatIsNotGradualIsDoneAtOnce) {
  Path p;
  p.kind = Path::Kind::at_once;
  EXPECT_TRUE(IncrementWalk(p, tolerances(), true).done());
  EXPECT_TRUE(IncrementWalk().done());
}

}  // namespace
}  // namespace membra
