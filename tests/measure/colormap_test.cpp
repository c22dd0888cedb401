// The colour map: exact at the ends, the midpoint, and when clamped.
#include <gtest/gtest.h>

#include "membra/measure/colormap.hpp"

namespace membra {
namespace {

void expect_rgb(const Rgb& c, float r, float g, float b) {
  EXPECT_FLOAT_EQ(c.x(), r);
  EXPECT_FLOAT_EQ(c.y(), g);
  EXPECT_FLOAT_EQ(c.z(), b);
}

TEST(Colormap, ThePapersBlueGreenRedWithClamping) {
  const ColourMap paper = ColourMap::paper;
  expect_rgb(colormap(-2.0, -2.0, 6.0, paper), 0, 0, 1);       // lo
  expect_rgb(colormap(2.0, -2.0, 6.0, paper), 0, 1, 0);        // midpoint
  expect_rgb(colormap(6.0, -2.0, 6.0, paper), 1, 0, 0);        // hi
  expect_rgb(colormap(-9.0, -2.0, 6.0, paper), 0, 0, 1);       // clamped below
  expect_rgb(colormap(1e9, -2.0, 6.0, paper), 1, 0, 0);        // clamped above
  expect_rgb(colormap(0.0, -2.0, 6.0, paper), 0, 0.5f, 0.5f);  // a quarter of the way
  expect_rgb(colormap(4.0, -2.0, 6.0, paper), 0.5f, 0.5f, 0);  // three quarters
}

// The default: ColorBrewer's RdBu stops, exact at its ends, its white middle and its stops.
TEST(Colormap, TheDefaultIsRdBuBlueWhiteRed) {
  expect_rgb(colormap(-2.0, -2.0, 6.0), 5 / 255.0f, 48 / 255.0f, 97 / 255.0f);     // lo
  expect_rgb(colormap(2.0, -2.0, 6.0), 247 / 255.0f, 247 / 255.0f, 247 / 255.0f);  // middle
  expect_rgb(colormap(6.0, -2.0, 6.0), 103 / 255.0f, 0, 31 / 255.0f);              // hi
  expect_rgb(colormap(1e9, -2.0, 6.0), 103 / 255.0f, 0, 31 / 255.0f);              // clamped
  expect_rgb(colormap(0.4, -2.0, 6.0), 146 / 255.0f, 197 / 255.0f, 222 / 255.0f);  // stop 3 of 10
  // Lightness runs down from the white middle to both ends, so that the sign reads without hue
  // (a deuteranope's view of a red-green map loses it): the grey level falls monotonically.
  const auto grey = [](const Rgb& c) { return 0.299f * c.x() + 0.587f * c.y() + 0.114f * c.z(); };
  for (int i = 0; i < 50; ++i) {
    EXPECT_LT(grey(colormap(i + 1, -50, 50)), grey(colormap(i, -50, 50)) + 1e-6f) << i;
    EXPECT_LT(grey(colormap(-i - 1, -50, 50)), grey(colormap(-i, -50, 50)) + 1e-6f) << i;
  }
  EXPECT_EQ(colour_map_named("paper"), ColourMap::paper);
  EXPECT_STREQ(to_string(colour_map_named("diverging")), "diverging");
  EXPECT_THROW(colour_map_named("jet"), std::invalid_argument);
}

TEST(Colormap, SymmetricRangeCoversEveryValueWithAFloor) {
  EXPECT_EQ(symmetric_range({-3.0, 1.0, 2.0}, 0.5), std::make_pair(-3.0, 3.0));
  EXPECT_EQ(symmetric_range({1e-12, -1e-13}, 1e-6), std::make_pair(-1e-6, 1e-6));
  const auto c = colorize({0.0, 1.0}, -1.0, 1.0, ColourMap::paper);
  expect_rgb(c[0], 0, 1, 0);
  expect_rgb(c[1], 1, 0, 0);
}

TEST(Colormap, PercentileRangeLetsAFewSpikesSaturate) {
  // 95 values of magnitude 1..95 and 5 spikes of 1000, with rim zeros: the 95th percentile of
  // the nonzero magnitudes is 95, the spikes saturate.
  std::vector<double> v(20, 0.0);
  for (int i = 1; i <= 95; ++i) v.push_back(i % 2 ? i : -i);
  for (int i = 0; i < 5; ++i) v.push_back(-1000.0);
  EXPECT_EQ(symmetric_percentile_range(v, 0.95, 1e-6), std::make_pair(-95.0, 95.0));
  EXPECT_EQ(symmetric_percentile_range(v, 1.0, 1e-6), std::make_pair(-1000.0, 1000.0));
  EXPECT_EQ(symmetric_percentile_range({0.0, 0.0}, 0.95, 0.5), std::make_pair(-0.5, 0.5));
  EXPECT_EQ(symmetric_percentile_range({1e-9}, 0.95, 1e-6), std::make_pair(-1e-6, 1e-6));
}

}  // namespace
}  // namespace membra
