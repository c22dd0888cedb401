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

TEST(Colormap, BlueGreenRedWithClamping) {
  expect_rgb(colormap(-2.0, -2.0, 6.0), 0, 0, 1);       // lo
  expect_rgb(colormap(2.0, -2.0, 6.0), 0, 1, 0);        // midpoint
  expect_rgb(colormap(6.0, -2.0, 6.0), 1, 0, 0);        // hi
  expect_rgb(colormap(-9.0, -2.0, 6.0), 0, 0, 1);       // clamped below
  expect_rgb(colormap(1e9, -2.0, 6.0), 1, 0, 0);        // clamped above
  expect_rgb(colormap(0.0, -2.0, 6.0), 0, 0.5f, 0.5f);  // a quarter of the way
  expect_rgb(colormap(4.0, -2.0, 6.0), 0.5f, 0.5f, 0);  // three quarters
}

TEST(Colormap, SymmetricRangeCoversEveryValueWithAFloor) {
  EXPECT_EQ(symmetric_range({-3.0, 1.0, 2.0}, 0.5), std::make_pair(-3.0, 3.0));
  EXPECT_EQ(symmetric_range({1e-12, -1e-13}, 1e-6), std::make_pair(-1e-6, 1e-6));
  const auto c = colorize({0.0, 1.0}, -1.0, 1.0);
  expect_rgb(c[0], 0, 1, 0);
  expect_rgb(c[1], 1, 0, 0);
}

}  // namespace
}  // namespace membra
