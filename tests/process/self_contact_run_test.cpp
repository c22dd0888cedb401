// Self-contact on a whole run (docs/model.md, "Self-contact"): a strip coated on one face curls
// to Timoshenko's radius, and a strip longer than that circle's circumference would, without
// contact, roll through itself (159 crossing triangle pairs on this mesh). With
// simulation.self_contact its outer turn lies on the inner one: the layers touch and none cross.
#include <gtest/gtest.h>

#include "membra/io/scene.hpp"
#include "membra/output/bench_report.hpp"
#include "membra/process/run.hpp"
#include "membra/process/scene_bench.hpp"

namespace membra {
namespace self_contact_run_test {
namespace {

// 140 x 30 mm latex stretched 1.5x along x, coated with 0.2 mm epoxy: it rolls to about 33 mm
// across, 140 mm of natural length round a circle of about 100 mm, past a full turn.
const char* kCoil = R"({
  "name": "coil", "model": "continuum",
  "materials": {"thin_epoxy": {"preset": "epoxy", "thickness": 0.2}},
  "sheet": {"size": [140, 30], "material": "latex", "mesh": {"max_edge": 8}},
  "simulation": {"solver": "newton", "G": 0, "self_contact": true},
  "protocol": [
    {"step": "stretch", "lambda": [1.5, 1.0]},
    {"step": "impregnate", "material": "thin_epoxy", "resin_side": "top", "bilayer": true,
     "pattern": {"polygon": {"points": [[-10, -10], [310, -10], [310, 210], [-10, 210]]}}},
    {"step": "release", "increments": 10, "perturbation": 0.2, "seed": 1}
  ]
})";

TEST(SelfContactRun, AStripRollingPastAFullTurnLaysItsTurnsOnEachOther) {
  const RunResult r = run_scene(parse_scene(nlohmann::json::parse(kCoil)));
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  EXPECT_EQ(r.self_intersection.pairs, 0);
  // The turns met: pairs nearer than the gap, pushed apart by the barrier, none at zero.
  EXPECT_GT(r.contact.touching, 5);
  EXPECT_GT(r.contact.min_distance, 0.3e-3);
  EXPECT_GT(r.contact_energy, 0.0);
  // Rolled, not unrolled by the contact: about the height of the roll without it (32.5 mm).
  EXPECT_NEAR(r.shape.height, 0.0325, 0.003);
}

// `membra bench --scenes` with a solver that has no step limit: a row that says why, written to
// the bench's JSON, and not a run that steps through the sheet; the bench goes on.
TEST(SelfContactRun, ABenchRowWhoseSolverCannotHoldContactSaysWhy) {
  const Scene coil = parse_scene(nlohmann::json::parse(kCoil));
  const SceneBenchRow row = bench_scene(coil, Solver::static_fire, 60.0);
  EXPECT_FALSE(row.report.converged);
  EXPECT_FALSE(row.over_budget);
  EXPECT_NE(row.error.find("self-contact"), std::string::npos) << row.error;
  EXPECT_EQ(row.report.iterations, 0);
  const nlohmann::json j = scene_bench_report({row});
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["solver"], "static");
  EXPECT_EQ(j[0]["error"], row.error);
  EXPECT_FALSE(j[0]["converged"].get<bool>());
}

}  // namespace
}  // namespace self_contact_run_test
}  // namespace membra
