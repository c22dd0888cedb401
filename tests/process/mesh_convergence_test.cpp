// The form converges with the mesh where the pattern has one smooth form (docs/forms.md, "With
// the mesh"): the paper's shrink-fabric saddle on grids of 8, 16 and 32 cells a side.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "process/example_run.hpp"

namespace membra {
namespace {

// Halving the spacing twice: the energy's change falls at least 4x (second order; measured 6.5x:
// 18.05, 19.54, 19.77 µJ, and 19.80 at 64² and 128²), the raw total Gaussian curvature's at
// least 2x (first order; measured 3.8x: -1.084, -1.240, -1.281 rad, -1.271 at 128²), and every
// grid reads the same global form.
TEST(MeshConvergence, TheShrinkSaddleConvergesWhenItsSpacingHalves) {
  std::array<double, 3> energy{}, k{};
  const std::array<int, 3> sizes = {9, 17, 33};
  for (size_t i = 0; i < sizes.size(); ++i) {
    const RunResult r = run_example("exp5_shrink.json", sizes[i]);
    ASSERT_TRUE(r.solve.converged && r.stability.stable) << sizes[i];
    EXPECT_EQ(r.form_global, "anticlastic") << sizes[i];
    energy[i] = r.elastic_energy + r.bending_energy;
    k[i] = r.curvature.total;
    std::printf("%d^2: energy %.4f uJ, raw K %.4f rad\n", sizes[i], 1e6 * energy[i], k[i]);
  }
  EXPECT_GT(std::abs(energy[1] - energy[0]), 4.0 * std::abs(energy[2] - energy[1]));
  EXPECT_GT(std::abs(k[1] - k[0]), 2.0 * std::abs(k[2] - k[1]));
  EXPECT_LT(k[2], 0.0);
}

}  // namespace
}  // namespace membra
