// The stencil calibration: what a square of resin per cell does, as a density, measured by
// membra on the design's own sheet (docs/inverse_design.md, the adjoint method's stage 3).
#include <gtest/gtest.h>

#include <cstdio>

#include "membra/design/stencil_calibration.hpp"
#include "membra/io/design_reader.hpp"

namespace membra {
namespace {

// 200 mm frame stretched 1.5 x 1.5, a 17 x 17 sheet, 20 mm cells, 4 mm minimum feature: squares
// from 4 to 16 mm a side, area shares from 0.04 to 0.64.
TEST(StencilCalibration, ASquaresShareActsAsAboutItsAreaInDensity) {
  const DesignSpec spec = parse_design({{"name", "calibration"},
                                        {"target", {{"saddle", {{"size", 150}, {"height", 15}}}}},
                                        {"frame", {{"size", 200}, {"lambda", {1.5, 1.5}}}},
                                        {"sheet", {{"resolution", 17}}},
                                        {"resin", {{"min_feature", 4}, {"cell", 20}}},
                                        {"design", {{"solver", "newton"}}}});
  const StencilCalibration c = calibrate_stencil(spec);
  ASSERT_EQ(c.share.size(), 6u);  // (0, 0), four squares, (1, 1)
  EXPECT_NEAR(c.min_share, 0.04, 1e-12);
  EXPECT_NEAR(c.max_share, 0.64, 1e-12);
  for (size_t k = 1; k + 1 < c.share.size(); ++k) {
    std::printf("share %.3f acts as density %.3f\n", c.share[k], c.density[k]);
    // Measured on 17² and 33² sheets: 1.1 to 1.3 times the share (the latex between squares
    // shrinks a little less than bare latex, held by the squares around it).
    EXPECT_GT(c.density[k], 0.9 * c.share[k]) << k;
    EXPECT_LT(c.density[k], 1.4 * c.share[k]) << k;
    EXPECT_GE(c.density[k], c.density[k - 1]) << k;
  }
  // What can be cut: nothing, a square between the limits, or a filled cell.
  EXPECT_EQ(c.share_for(0.0), 0.0);
  EXPECT_EQ(c.share_for(1.0), 1.0);
  EXPECT_NEAR(c.share_for(c.density_of(0.3)), 0.3, 1e-9);
  EXPECT_EQ(c.share_for(0.5 * c.density_of(0.5 * c.min_share)), 0.0);
  EXPECT_EQ(c.share_for(c.density_of(0.9)), 1.0);
  EXPECT_EQ(c.share_for(c.density_of(0.7)), c.max_share);
}

}  // namespace
}  // namespace membra
