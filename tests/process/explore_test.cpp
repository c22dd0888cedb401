// simulation.explore: the distinct stable forms of a scene, found by releasing it with other
// imperfections.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "membra/io/scene.hpp"
#include "membra/measure/form_distance.hpp"
#include "membra/output/report.hpp"
#include "membra/process/explore.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

// A strip held at both ends and grown 2 % along its length: it must buckle, up or down, two
// mirror-image minima of equal energy (its ends are pinned, so the two are distinct forms).
Scene buckling_strip(int explore) {
  return parse_scene(nlohmann::json::parse(R"({
    "name": "strip",
    "sheet": {"size": [100, 10], "resolution": [21, 3], "material": "latex"},
    "pins": [{"edge": "left"}, {"edge": "right"}],
    "simulation": {"solver": "newton", "G": 0, "explore": )" +
                                           std::to_string(explore) + R"(},
    "protocol": [{"step": "grow", "factor": 1.02, "direction": "x", "increments": 4}]
  })"));
}

TEST(Explore, FindsBothBranchesOfAStripThatBucklesUpOrDown) {
  const int n = 12;
  const RunResult r = run_scene(buckling_strip(n));
  ASSERT_EQ(r.explored, n);
  ASSERT_EQ(r.branches.size(), 2u) << "unsettled " << r.unsettled;
  EXPECT_EQ(r.unsettled, 0);
  int found = 0;
  double z_sign[2];
  for (int b = 0; b < 2; ++b) {
    const RunResult& f = r.branches[b].run;
    found += static_cast<int>(r.branches[b].releases.size());
    const Points& x = f.prepared.membrane.state.x;
    z_sign[b] = x.row(2).sum() > 0 ? 1.0 : -1.0;
    EXPECT_GT(f.shape.height, 2e-3) << "buckled by millimetres";
    // About equal counts: each at least a quarter of the releases.
    EXPECT_GE(r.branches[b].releases.size(), static_cast<size_t>(n / 4));
  }
  EXPECT_EQ(found, n);
  EXPECT_EQ(z_sign[0], -z_sign[1]) << "one up, one down";
  const RunResult& a = r.branches[0].run;
  const RunResult& b = r.branches[1].run;
  const double ea = a.elastic_energy + a.bending_energy, eb = b.elastic_energy + b.bending_energy;
  EXPECT_NEAR(ea / eb, 1.0, 1e-6) << "mirror images: equal energies";
  // Mirror images: z flipped, the same form.
  Points mirrored = b.prepared.membrane.state.x;
  mirrored.row(2) *= -1.0;
  EXPECT_LT(form_distance(a.prepared.membrane.state.x, mirrored, false), 1e-6);
  // Release 0 is the scene's own: the bump towards the resin side (top, +z).
  EXPECT_EQ(r.prepared.membrane.state.x.row(2).sum() > 0, true);
}

TEST(Explore, TheReportListsTheBranches) {
  const RunResult r = run_scene(buckling_strip(4));
  const nlohmann::json j = make_report(buckling_strip(4), r);
  ASSERT_TRUE(j.contains("branches"));
  EXPECT_EQ(j["explore"]["releases"], 4);
  int count = 0;
  for (const auto& b : j["branches"]) {
    count += b["count"].get<int>();
    EXPECT_EQ(b["output"], "branches/" + std::to_string(b["index"].get<int>()) + "/");
    EXPECT_GT(b["height"].get<double>(), 2.0);   // mm
    EXPECT_EQ(b["self_intersection_pairs"], 0);  // a buckled strip does not cross itself
  }
  EXPECT_EQ(count + j["explore"]["unsettled"].get<int>(), 4);
  EXPECT_FALSE(make_report(buckling_strip(1), run_scene(buckling_strip(1))).contains("branches"));
}

TEST(Explore, OnlyEquilibriumSolversExplore) {
  nlohmann::json j =
      nlohmann::json::parse(R"({"name": "x", "sheet": {"size": [100, 100], "resolution": [5, 5]},
    "simulation": {"solver": "rk4",
    "explore": 3}})");
  try {
    parse_scene(j);
    FAIL() << "rk4 with explore accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/simulation/explore");
  }
}

TEST(FormDistance, IgnoresRigidMotionsButNotMirrors) {
  Points a(3, 4);
  a << 0, 1, 0, 0.3,  //
      0, 0, 1, 0.2,   //
      0, 0, 0, 0.5;
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Points moved = (rot * a).colwise() + Vec3(5, -2, 1);
  EXPECT_LT(form_distance(a, moved, true), 1e-12);
  EXPECT_GT(form_distance(a, moved, false), 1.0);
  Points mirror = a;
  mirror.row(2) *= -1.0;  // a chiral tetrahedron's mirror image is no rigid motion of it
  EXPECT_GT(form_distance(a, mirror, true), 0.05);
}

}  // namespace
}  // namespace membra
