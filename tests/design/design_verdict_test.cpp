// The design's verdict against the goal and a flat sheet (docs/inverse_design.md, "The verdict").
#include "membra/design/design_verdict.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "membra/design/design_result.hpp"

namespace membra {
namespace {

// A design whose stencil settled with the errors given (% of the diameter).
DesignResult design_with(double rms, double flat, int pieces = 40) {
  DesignResult r;
  r.method = "pattern_search";
  r.rms_error = rms;
  r.flat_error = flat;
  r.stencil.pieces = pieces;
  r.run.solve.converged = true;
  return r;
}

TEST(DesignVerdict, MeetsTheGoalOnlyWithinTwoPercentAndHalfAFlatSheet) {
  DesignResult fine = design_with(1.5, 4.0);
  fine.spec.resolution = 33;
  EXPECT_EQ(design_verdict(fine).grade, "meets_goal");
  EXPECT_EQ(design_verdict(fine).sentence.find("coarse"), std::string::npos);
  DesignResult coarse = fine;  // the goal's numbers, but on a coarse sheet: said so
  coarse.spec.resolution = 17;
  EXPECT_EQ(design_verdict(coarse).grade, "meets_goal");
  EXPECT_NE(design_verdict(coarse).sentence.find("on a 17 x 17 sheet (check it on 33 x 33"),
            std::string::npos)
      << design_verdict(coarse).sentence;
  EXPECT_EQ(design_verdict(design_with(2.0, 4.0)).grade, "meets_goal");  // both bounds inclusive
  // Within 2 % but more than half a flat sheet's 2.5 %: closer than flat, not the goal.
  EXPECT_EQ(design_verdict(design_with(1.5, 2.5)).grade, "closer_than_flat");
  // Half a flat sheet's but over 2 %.
  EXPECT_EQ(design_verdict(design_with(2.4, 6.0)).grade, "closer_than_flat");
}

TEST(DesignVerdict, AStencilBarelyBelowAFlatSheetIsNoDesign) {
  // The pattern search's saddle at 33^2: a bare sheet, 4.17 % against a flat sheet's 4.29 %.
  const DesignVerdict v = design_verdict(design_with(4.17, 4.29, 0));
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("no resin"), std::string::npos) << v.sentence;
  EXPECT_NE(v.sentence.find("adjoint"), std::string::npos) << v.sentence;        // what to try
  EXPECT_EQ(design_verdict(design_with(3.86, 4.29)).grade, "closer_than_flat");  // 0.9 of flat
  EXPECT_EQ(design_verdict(design_with(3.87, 4.29)).grade, "no_closer_than_flat");
}

// A target that bends with little Gaussian curvature (a cylinder) is pointed at a coat on one
// face rather than at the adjoint's densities; a cap, whose curvature is Gaussian, is not: it is a
// dome, pointed at darts (and a design with darts at other numbers of them, and at a coat for them
// to cut through); nor is a design that already has the coat (the adjoint cannot place one).
TEST(DesignVerdict, ABentTargetIsPointedAtACoatOnOneFace) {
  DesignResult cylinder = design_with(3.0, 4.0);
  TargetSpec spec;
  spec.kind = "cylinder";
  spec.height = 0.02;
  cylinder.target = make_target(spec);
  DesignVerdict v = design_verdict(cylinder);
  EXPECT_NE(v.sentence.find("\"bilayer\": true"), std::string::npos) << v.sentence;
  EXPECT_EQ(v.sentence.find("adjoint"), std::string::npos) << v.sentence;
  DesignResult cap = design_with(3.0, 4.0);
  spec = TargetSpec{};  // a cap 150 mm across, 22.5 mm high
  cap.target = make_target(spec);
  v = design_verdict(cap);
  EXPECT_EQ(v.sentence.find("bilayer"), std::string::npos) << v.sentence;
  EXPECT_NE(v.sentence.find("\"layout\": \"darts\""), std::string::npos) << v.sentence;
  DesignResult saddle = design_with(3.0, 4.0);
  spec.kind = "saddle";
  saddle.target = make_target(spec);
  v = design_verdict(saddle);
  EXPECT_NE(v.sentence.find("\"fisheye_darts\""), std::string::npos) << v.sentence;
  cap.spec.layout.kind = "darts";
  v = design_verdict(cap);
  EXPECT_NE(v.sentence.find("another number of darts"), std::string::npos) << v.sentence;
  EXPECT_NE(v.sentence.find("\"resin_side\": \"convex\""), std::string::npos) << v.sentence;
  EXPECT_EQ(v.sentence.find("adjoint"), std::string::npos) << v.sentence;
  cap.spec.bilayer = true;  // darts through a coat already
  v = design_verdict(cap);
  EXPECT_EQ(v.sentence.find("\"resin_side\""), std::string::npos) << v.sentence;
  cylinder.spec.bilayer = true;
  v = design_verdict(cylinder);
  EXPECT_EQ(v.sentence.find("bilayer"), std::string::npos) << v.sentence;
  EXPECT_EQ(v.sentence.find("adjoint"), std::string::npos) << v.sentence;
}

TEST(DesignVerdict, AFormThatDidNotSettleMeetsNothingAndSaysWhy) {
  DesignResult r = design_with(1.0, 4.0);
  r.run.solve.converged = false;
  DesignVerdict v = design_verdict(r);
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("ended unconverged, so its form is no prediction"), std::string::npos)
      << v.sentence;
  r = design_with(1.0, 4.0);  // converged, but the stability check found a saddle point
  r.run.stability.checked = true;
  r.run.stability.stable = false;
  v = design_verdict(r);
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("at a saddle point"), std::string::npos) << v.sentence;
  r = design_with(1.0, 4.0);
  r.run.out_of_time = true;
  EXPECT_NE(design_verdict(r).sentence.find("ran out of its time"), std::string::npos);
  r = design_with(std::numeric_limits<double>::quiet_NaN(), 4.0);
  v = design_verdict(r);
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("no measurable form"), std::string::npos) << v.sentence;
  EXPECT_EQ(v.sentence.find("nan"), std::string::npos) << v.sentence;
}

TEST(DesignVerdict, AnUnreachableTargetIsSaidToBeOutOfReachWithoutAMethodToTry) {
  DesignResult r = design_with(8.0, 4.0);
  r.reachable = false;
  const DesignVerdict v = design_verdict(r);
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("out of reach"), std::string::npos) << v.sentence;
  EXPECT_EQ(v.sentence.find("try"), std::string::npos) << v.sentence;
}

TEST(DesignVerdict, NamesABareStencilWhateverItsGrade) {
  // A bare sheet can score clearly below a flat one (a shrunk, gently buckled sheet).
  const DesignVerdict v = design_verdict(design_with(3.0, 4.29, 0));
  EXPECT_EQ(v.grade, "closer_than_flat");
  EXPECT_NE(v.sentence.find("no resin"), std::string::npos) << v.sentence;
}

TEST(DesignVerdict, AnAdjointDesignNamesItsDensityDesignsError) {
  DesignResult r = design_with(6.33, 4.29);
  r.method = "adjoint";
  r.density_rms_error = 0.22;
  const DesignVerdict v = design_verdict(r);
  EXPECT_EQ(v.grade, "no_closer_than_flat");
  EXPECT_NE(v.sentence.find("density design (density.png) releases to within 0.22 % of the target"),
            std::string::npos)
      << v.sentence;
  EXPECT_EQ(v.sentence.find("try"), std::string::npos) << v.sentence;
  r.density_rms_error = 7.0;  // a density design no closer than its stencil is not held up
  EXPECT_EQ(design_verdict(r).sentence.find("density design"), std::string::npos)
      << design_verdict(r).sentence;
}

}  // namespace
}  // namespace membra
