// Shape summaries.
#include <cmath>

#include <gtest/gtest.h>

#include "membra/measure/shape.hpp"

namespace membra {
namespace {

TEST(Shape, TiltedPlaneHasNoHeight) {
  Points x(3, 100);
  for (int i = 0; i < 100; ++i) {
    const double u = i % 10, v = i / 10;
    x.col(i) = Vec3(u, v, 0.5 * u - 0.25 * v);
  }
  const ShapeSummary s = summarize_shape(x);
  EXPECT_NEAR(s.height, 0.0, 1e-9);
  EXPECT_NEAR(s.z_range, 0.5 * 9 + 0.25 * 9, 1e-12);
  EXPECT_NEAR(std::abs(s.normal.dot(Vec3(-0.5, 0.25, 1).normalized())), 1.0, 1e-12);
}

TEST(Shape, SymmetricBumpHeightIsItsPeak) {
  // z = h (1 - r^2) on a symmetric grid: the best-fit plane is horizontal, height = h.
  Points x(3, 21 * 21);
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 21; ++i) {
      const double u = (i - 10) / 10.0, v = (j - 10) / 10.0;
      x.col(j * 21 + i) = Vec3(u, v, 0.1 * (2.0 - u * u - v * v));
    }
  const ShapeSummary s = summarize_shape(x);
  EXPECT_NEAR(s.height, 0.2, 1e-12);
  EXPECT_NEAR(s.normal.z(), 1.0, 1e-12);
}

}  // namespace
}  // namespace membra
