// A lattice grid too coarse for its pattern is said, with a resolution that resolves it
// (docs/forms.md, "When the grid is too coarse").
#include "membra/process/grid_resolution.hpp"

#include <gtest/gtest.h>

#include <string>

#include "membra/io/scene.hpp"

namespace membra {
namespace {

const std::string kGridExamples = std::string(MEMBRA_SOURCE_DIR) + "/examples/";

// exp3's resin strips are 12 mm wide: 1.2 spacings at 21 x 21 (the grid where it reads a bowl
// instead of a tube), 2.4 at its own 41 x 41. 12 mm / 2 spacings asks for 6 mm, 35 x 35 nodes.
TEST(GridResolution, Exp3At21WarnsAndNamesAResolutionThatResolvesIt) {
  const auto coarse =
      coarse_grid(load_scene(kGridExamples + "exp3_parallel.json", {"sheet.resolution=[21,21]"}));
  ASSERT_TRUE(coarse.has_value());
  EXPECT_NEAR(coarse->width, 0.012, 1e-4);
  EXPECT_NEAR(coarse->spacing, 0.010, 1e-12);
  EXPECT_EQ(coarse->resolution[0], 35);
  EXPECT_EQ(coarse->resolution[1], 35);
  EXPECT_NE(coarse->message.find("sheet.resolution"), std::string::npos);
  EXPECT_NE(coarse->message.find("12 mm across"), std::string::npos);
  EXPECT_NE(coarse->message.find("[35, 35]"), std::string::npos);
  // The resolution it names resolves it.
  EXPECT_FALSE(
      coarse_grid(load_scene(kGridExamples + "exp3_parallel.json", {"sheet.resolution=[35,35]"})));
}

// A strip coated all over, 10 mm wide on a grid of 5.02 mm (the larger of its two spacings): the
// narrowest feature is the sheet itself, a hair under two spacings; the message must not call
// it 2 spacings while it asks for 2.
TEST(GridResolution, AFeatureJustUnderTwoSpacingsDoesNotReadAsTwo) {
  const auto coarse = coarse_grid(parse_scene(nlohmann::json::parse(R"({
    "name": "strip", "sheet": {"size": [110.4, 10], "resolution": [23, 3]},
    "protocol": [{"step": "stretch", "lambda": [1.5, 1.0]},
      {"step": "impregnate", "bilayer": true, "pattern": {"polygon": {"points":
        [[-10, -10], [310, -10], [310, 210], [-10, 210]]}}}]})")));
  ASSERT_TRUE(coarse.has_value());
  EXPECT_LT(coarse->width, 2.0 * coarse->spacing);
  EXPECT_EQ(coarse->message.find(" 2 grid spacings"), std::string::npos) << coarse->message;
  EXPECT_NE(coarse->message.find("1.99 grid spacings"), std::string::npos) << coarse->message;
}

TEST(GridResolution, ResolvedPatternlessAndContinuumScenesSayNothing) {
  EXPECT_FALSE(coarse_grid(load_scene(kGridExamples + "exp3_parallel.json")));
  EXPECT_FALSE(coarse_grid(load_scene(kGridExamples + "exp1_basic.json")));
  EXPECT_FALSE(coarse_grid(load_scene(kGridExamples + "exp3_parallel.json",
                                      {"model=continuum", "sheet.resolution=[21,21]"})));
}

}  // namespace
}  // namespace membra
