// Numbers on legends and report pages: readable units and digits.
#include <gtest/gtest.h>

#include "membra/core/readable_units.hpp"

namespace membra {
namespace {

// One unit per quantity, whatever the values' size (docs/outputs.md, "Units").
TEST(ReadableUnits, CurvatureIsAlwaysInPerSquareMetre) {
  // 6.3e-6 1/mm^2 (a radius of 0.4 m) reads as 6.3 1/m^2; so does a sharp 0.02 1/mm^2.
  const DisplayUnit u = readable_unit("1/mm^2", 6.3e-6);
  EXPECT_EQ(u.unit, "1/m²");
  EXPECT_EQ(format_number(6.3e-6 * u.factor, 1.0), "6.3");
  EXPECT_EQ(readable_unit("1/mm^2", 0.02).unit, "1/m²");
  EXPECT_EQ(readable_unit("1/m^2", 2e4).unit, "1/m²");
  EXPECT_DOUBLE_EQ(readable_unit("1/m^2", 2e4).factor, 1.0);
}

TEST(ReadableUnits, StressIsAlwaysInMegapascal) {
  for (double v : {1.2, 4.2e-4, 2e-5}) {
    EXPECT_EQ(readable_unit("MPa", v).unit, "MPa") << v;
    EXPECT_DOUBLE_EQ(readable_unit("MPa", v).factor, 1.0) << v;
  }
  EXPECT_EQ(readable_unit("N/mm^2", 1.0).unit, "N/mm²");
}

TEST(ReadableUnits, DigitsFollowTheSpacingAndTheMinusIsTrue) {
  EXPECT_EQ(format_number(0.5, 0.25), "0.50");
  EXPECT_EQ(format_number(597.3, 298.6), "597");
  EXPECT_EQ(format_number(-1.88e-5 * 1e6, 9.4), "\u221218.8");
  EXPECT_EQ(format_number(-0.0001, 1.0), "0.0");  // no "-0.0"
  EXPECT_EQ(format_number(2.5e7, 1e6), "2.50e+07");
}

TEST(ReadableUnits, TicksOfTheLegendThatWasCutOff) {
  // exp4's legend printed "-1.88e-03" for -1.88e-05 1/mm^2: now -18.8 .. 18.8 1/m^2.
  const Ticks t = readable_ticks(-1.88e-5, 1.88e-5, "1/mm^2", 5);
  EXPECT_EQ(t.unit, "1/m²");
  ASSERT_EQ(t.labels.size(), 5u);
  EXPECT_EQ(t.labels.front(), "\u221218.8");
  EXPECT_EQ(t.labels[2], "0.0");
  EXPECT_EQ(t.labels.back(), "18.8");
  // A stress legend of 4.2e-4 MPa stays in MPa, with the digits it needs.
  const Ticks s = readable_ticks(-4.2e-4, 4.2e-4, "MPa", 5);
  EXPECT_EQ(s.unit, "MPa");
  EXPECT_EQ(s.labels.back(), "0.00042");
}

}  // namespace
}  // namespace membra
