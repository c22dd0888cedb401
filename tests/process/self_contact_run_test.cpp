// Self-contact on a whole run (docs/model.md, "Self-contact"): a strip coated on one face curls
// to Timoshenko's radius, and a strip longer than that circle's circumference would, without
// contact, roll through itself (129 crossing triangle pairs on this mesh). With
// simulation.self_contact its outer turn lies on the inner one: the layers touch and none cross.
#include <gtest/gtest.h>

#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace self_contact_run_test {
namespace {

// 200 x 30 mm latex stretched 1.5x along x, coated with 0.2 mm epoxy: it rolls to about 33 mm
// across, 300 mm of frame length round a circle of about 100 mm.
const char* kCoil = R"({
  "name": "coil", "model": "continuum",
  "materials": {"thin_epoxy": {"preset": "epoxy", "thickness": 0.2}},
  "sheet": {"size": [200, 30], "material": "latex", "mesh": {"max_edge": 8}},
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
  // Rolled, not unrolled by the contact: about the height of the roll without it (33.2 mm).
  EXPECT_NEAR(r.shape.height, 0.0332, 0.003);
}

}  // namespace
}  // namespace self_contact_run_test
}  // namespace membra
