// The stencil calibration: what a square of resin per cell does, as a density, measured by
// membra on the design's own sheet (docs/inverse_design.md, the adjoint method's stage 3).
#include <gtest/gtest.h>

#include <cstdio>

#include <filesystem>

#include "membra/design/stencil_calibration.hpp"
#include "membra/io/design_reader.hpp"
#include "membra/output/calibration_store.hpp"

namespace membra {
namespace {

// 200 mm frame stretched 1.5 x 1.5, a 17 x 17 sheet, 20 mm cells, 4 mm minimum feature: squares
// from 4 to 16 mm a side, area shares from 0.04 to 0.64.
TEST(StencilCalibration, ASquaresShareActsAsAboutItsAreaInDensity) {
  DesignSpec spec = parse_design({{"name", "calibration"},
                                  {"target", {{"saddle", {{"size", 150}, {"height", 15}}}}},
                                  {"frame", {{"size", 200}, {"lambda", {1.5, 1.5}}}},
                                  {"sheet", {{"resolution", 17}}},
                                  {"resin", {{"min_feature", 4}, {"cell", 20}}},
                                  {"design", {{"solver", "newton"}}}});
  const auto cache_dir =
      std::filesystem::temp_directory_path() /
      ("membra_calibration_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(cache_dir);
  spec.calibration_cache = calibration_store(cache_dir);
  const StencilCalibration c = calibrate_stencil(spec);
  EXPECT_FALSE(c.cached);  // measured, and stored
  // A second design on the same sheet reads it back instead of measuring it again.
  const StencilCalibration again = calibrate_stencil(spec);
  EXPECT_TRUE(again.cached);
  EXPECT_EQ(again.share, c.share);
  EXPECT_EQ(again.density, c.density);
  EXPECT_EQ(again.measured, c.measured);
  std::filesystem::remove_all(cache_dir);
  ASSERT_EQ(c.share.size(), 6u);  // (0, 0), four squares, (1, 1)
  EXPECT_NEAR(c.min_share, 0.04, 1e-8);
  EXPECT_NEAR(c.max_share, 0.64, 1e-8);
  // The limits as the layout sees them: the smallest square is cut, the largest leaves a gap.
  const Box2 frame{Vec2::Zero(), Vec2(0.2, 0.2)};
  const double lo = c.min_share, hi = c.max_share;
  EXPECT_EQ(layout_stencil([lo](const Vec2&) { return lo; }, frame, spec.layout).pieces, 100);
  EXPECT_LT(layout_stencil([hi](const Vec2&) { return hi; }, frame, spec.layout).resin_share, 0.65);
  ASSERT_EQ(c.measured.size(), 4u);
  for (size_t k = 0; k < c.measured.size(); ++k) {
    const double a = c.share[k + 1], rho = c.measured[k];
    std::printf("share %.3f acts as density %.3f\n", a, rho);
    // Measured on 17² and 33² sheets: 1.1 to 1.3 times the share (the latex between squares
    // shrinks a little less than bare latex, held by the squares around it).
    EXPECT_GT(rho, 0.9 * a) << k;
    EXPECT_LT(rho, 1.4 * a) << k;
    if (k > 0) {
      EXPECT_GT(rho, c.measured[k - 1]) << k;  // as measured, before any smoothing
    }
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
