// The advice a run carries before its form is trusted (process/run.hpp, run_warnings): here, a
// form that passes through itself (docs/measures.md, "A form that passes through itself"). A real
// run that does (exp3 at 21 x 21) is tested with its pictures (tests/render/run_pictures_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"
#include "process/crossing_warning.hpp"

namespace membra {
namespace run_warnings_test {
namespace {

const std::string kExamples = std::string(MEMBRA_SOURCE_DIR) + "/examples/";

using test_support::says_it_passes_through_itself;

// The message names the count and the place, in mm; a form that does not cross says nothing.
TEST(RunWarnings, TheMessageNamesHowManyAndWhere) {
  const Scene scene = load_scene(kExamples + "exp1_basic.json");
  RunResult r;
  r.self_intersection.pairs = 12;
  r.self_intersection.triangles = {1, 2, 3};
  r.self_intersection.at = Vec3(0.010, -0.020, 0.030);
  const std::vector<std::string> w = run_warnings(scene, r);
  ASSERT_TRUE(says_it_passes_through_itself(w));
  const std::string& m = w.back();
  EXPECT_NE(m.find("12 pairs of triangles"), std::string::npos) << m;
  EXPECT_NE(m.find("(10, -20, 30) mm"), std::string::npos) << m;
  EXPECT_NE(m.find("no self-contact"), std::string::npos) << m;
  r.self_intersection = {};
  EXPECT_FALSE(says_it_passes_through_itself(run_warnings(scene, r)));
}

// An impregnate step whose pattern the mesh does not follow is named with its count of triangles
// across the outline; none across says nothing.
TEST(RunWarnings, TrianglesAcrossAPatternsOutlineAreNamedByStep) {
  const Scene scene = load_scene(kExamples + "exp1_basic.json");
  RunResult r;
  r.steps.resize(3);
  r.steps[1].name = "impregnate";
  r.steps[1].pointer = "/protocol/1";
  EXPECT_TRUE(run_warnings(scene, r).empty());
  r.steps[1].partly_covered = 7;
  const std::vector<std::string> w = run_warnings(scene, r);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("/protocol/1: 7 triangles of the mesh lie across", 0), 0u) << w[0];
}

// With simulation.explore, another form that crosses itself is named by its branch; the form
// release 0 ended in is the run's own, said once.
TEST(RunWarnings, AnExploredFormThatCrossesItselfIsNamed) {
  const Scene scene = load_scene(kExamples + "exp1_basic.json");
  RunResult r;
  r.self_intersection.pairs = 3;
  r.branches.resize(3);
  r.branches[0].releases = {0, 2};
  r.branches[0].run.self_intersection.pairs = 3;
  r.branches[1].releases = {1};
  r.branches[1].run.self_intersection.pairs = 7;
  r.branches[2].releases = {3};
  const std::vector<std::string> w = run_warnings(scene, r);
  int explored = 0;
  for (const std::string& m : w)
    if (m.find("simulation.explore") != std::string::npos) {
      ++explored;
      EXPECT_NE(m.find("form 2 (branches/2/)"), std::string::npos) << m;
      EXPECT_NE(m.find("7 pairs"), std::string::npos) << m;
    }
  EXPECT_EQ(explored, 1);
}

}  // namespace
}  // namespace run_warnings_test
}  // namespace membra
