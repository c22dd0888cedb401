// Shape summaries.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "membra/measure/curvature.hpp"
#include "membra/measure/shape.hpp"
#include "membra/model/sheet.hpp"

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

class ShapeSplit : public ::testing::TestWithParam<int> {};

// On 81 x 81 every neighbour counts; on 257 x 257 (800 per window) every second one.
TEST_P(ShapeSplit, FoldsOnASaddleAreSplitFromItsGlobalShape) {
  // z = h (u^2 - v^2) + a sin(8 pi v) on a 2 x 2 sheet, tilted. The window is a disk of radius
  // 2/16 on the paper, whose average of a quadric is the quadric (the u^2 and v^2 terms gain the
  // same constant) and of the corrugation (k R = pi) is 2 J1(pi)/pi = 0.181 of it: the global
  // height is the saddle's 2h, the folds 0.819 of the corrugation (rms a/sqrt 2).
  const int n = GetParam();
  const double h = 0.05, a = 0.01;
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.3, Vec3(1, 2, 0).normalized()).matrix();
  Points x(3, n * n), paper(3, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = -1.0 + 2.0 * i / (n - 1), v = -1.0 + 2.0 * j / (n - 1);
      paper.col(j * n + i) = Vec3(u, v, 0.0);
      x.col(j * n + i) =
          tilt * Vec3(u, v, h * (u * u - v * v) + a * std::sin(8.0 * std::numbers::pi * v));
    }
  const ShapeSummary s = summarize_shape(x, paper);
  EXPECT_NEAR(s.global_height, 2.0 * h, 0.1 * 2.0 * h);
  EXPECT_NEAR(s.fold_rms, 0.819 * a / std::sqrt(2.0), 0.1 * a);
  EXPECT_GT(s.height, s.global_height);
  // Without paper positions there is no split.
  EXPECT_EQ(summarize_shape(x).global_height, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Grids, ShapeSplit, ::testing::Values(81, 257));

TEST(Shape, ARolledTubeIsGlobalNotFolded) {
  // A sheet rolled once round a cylinder of radius R: averaging over 1/16 of its length keeps
  // the tube (its diameter shrinks by the window's sinc, under 2 %).
  const int n = 65;
  const double length = 0.2, radius = length / (2.0 * std::numbers::pi);
  Points x(3, n * n), paper(3, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = length * i / (n - 1), v = length * j / (n - 1);
      paper.col(j * n + i) = Vec3(u, v, 0.0);
      const double phi = u / radius;
      x.col(j * n + i) = Vec3(radius * std::sin(phi), v, radius * (1.0 - std::cos(phi)));
    }
  const ShapeSummary s = summarize_shape(x, paper);
  EXPECT_NEAR(s.height, 2.0 * radius, 0.01 * radius);
  EXPECT_GT(s.global_height, 0.95 * s.height);
  EXPECT_LT(s.fold_rms, 0.05 * radius);
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

// A smooth bowl and a smooth saddle on coarse grids: the global form's total curvature is the
// form's own (nothing to average out), within 10 %. The window's mean used to pull the rim
// inwards, which folded it: 17 x 17 released examples read +13 to +28 rad.
class CoarseGlobalForm : public ::testing::TestWithParam<int> {};

TEST_P(CoarseGlobalForm, KeepsTheTotalCurvatureOfASmoothForm) {
  const int n = GetParam();
  const Sheet s = build_sheet({0.2, 0.2, n, n}, SheetOptions{});
  for (double sign : {1.0, -1.0}) {
    Points x = s.model.reference;
    for (Eigen::Index p = 0; p < x.cols(); ++p) {
      const double u = x(0, p) - 0.1, v = x(1, p) - 0.1;
      x(2, p) = (u * u + sign * v * v) / (2.0 * 0.15);
    }
    GaussianCurvature raw = gaussian_curvature(x, s.triangles);
    GaussianCurvature global = gaussian_curvature(global_form(x, s.model.reference), s.triangles);
    std::printf("%d x %d %s: raw %.3f, global %.3f rad\n", n, n, sign > 0 ? "bowl" : "saddle",
                raw.total, global.total);
    EXPECT_NEAR(global.total / raw.total, 1.0, 0.10) << (sign > 0 ? "bowl" : "saddle");
  }
}

INSTANTIATE_TEST_SUITE_P(Grids, CoarseGlobalForm, ::testing::Values(13, 17, 21, 41));

// Cells five times longer than wide (5 x 21 particles on a square): the window must reach the
// next column, or each window is one line of particles and the global form of a tilted plane
// is pulled in at the ends of every column. A linear fit over a two-dimensional window
// reproduces a plane exactly.
TEST(GlobalForm, ATiltedPlaneOnLongCellsIsItsOwnGlobalForm) {
  const Sheet s = build_sheet({0.1, 0.1, 5, 21}, SheetOptions{});
  Points x = s.model.reference;
  for (Eigen::Index p = 0; p < x.cols(); ++p) x(2, p) = 0.3 * x(0, p) - 0.5 * x(1, p);
  const Points g = global_form(x, s.model.reference);
  ASSERT_EQ(g.cols(), x.cols());
  EXPECT_LT((g - x).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace membra
