// The whole form's best-fit quadric: principal curvatures of analytic surfaces laid on a paper
// grid, independent of how the surface lies in space and of wrinkles on it.
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "membra/measure/quadric_fit.hpp"

namespace membra {
namespace {

constexpr double kPaperSide = 0.2;  // m: the paper's side
constexpr int kGridN = 21;

// A kGridN x kGridN paper grid over kPaperSide (m), mapped to space by `surface` (paper x, y from
// the centre).
struct LaidPaper {
  Points x, paper;
};
LaidPaper lay(const std::function<Vec3(double, double)>& surface) {
  LaidPaper l{Points(3, kGridN * kGridN), Points(3, kGridN * kGridN)};
  for (int j = 0; j < kGridN; ++j)
    for (int i = 0; i < kGridN; ++i) {
      const double u = kPaperSide * i / (kGridN - 1), v = kPaperSide * j / (kGridN - 1);
      l.paper.col(j * kGridN + i) = Vec3(u, v, 0.0);
      l.x.col(j * kGridN + i) = surface(u - 0.5 * kPaperSide, v - 0.5 * kPaperSide);
    }
  return l;
}

// A sphere of radius r, the paper laid on it by geodesic polar coordinates (lengths kept along
// the radii): so the fit sees a real sheet's kind of parametrisation, not a height field's.
Vec3 on_sphere(double u, double v, double r) {
  const double s = std::hypot(u, v);
  if (s == 0.0) return Vec3::Zero();
  const double rho = r * std::sin(s / r);
  return Vec3(rho * u / s, rho * v / s, r * (1.0 - std::cos(s / r)));
}

TEST(QuadricFit, ASphereHasBothCurvaturesOneOverItsRadius) {
  const double r = 0.4;
  const LaidPaper l = lay([&](double u, double v) { return on_sphere(u, v, r); });
  const QuadricFit q = fit_quadric(l.x, l.paper);
  ASSERT_TRUE(q.valid);
  // The quadric averages the sphere over the sheet; its quartic terms bias it (here by 1.3 %).
  EXPECT_NEAR(q.k1 * r, 1.0, 0.02);
  EXPECT_NEAR(q.k2 * r, 1.0, 0.02);
  EXPECT_EQ(q.classification, "synclastic");
  EXPECT_LT(q.rms, 1e-3 * kPaperSide);
  // Turned over, a bowl is still a bowl: the normal is chosen so that k1 + k2 >= 0.
  Points flipped = l.x;
  flipped.row(2) *= -1.0;
  const QuadricFit down = fit_quadric(flipped, l.paper);
  EXPECT_NEAR(down.k1, q.k1, 1e-9 * std::abs(q.k1));
  EXPECT_NEAR(down.k2, q.k2, 1e-9 * std::abs(q.k1));
}

TEST(QuadricFit, ASaddleHasCurvaturesOfOppositeSign) {
  // z = (x^2 - y^2) / (2 r): a quadratic height field, fitted exactly; k = +-1/r at the centre.
  const double r = 0.3;
  const LaidPaper l =
      lay([&](double u, double v) { return Vec3(u, v, (u * u - v * v) / (2.0 * r)); });
  const QuadricFit q = fit_quadric(l.x, l.paper);
  ASSERT_TRUE(q.valid);
  EXPECT_NEAR(q.k1 * r, 1.0, 1e-9);
  EXPECT_NEAR(q.k2 * r, -1.0, 1e-9);
  EXPECT_EQ(q.classification, "anticlastic");
  EXPECT_LT(q.rms, 1e-12);
}

TEST(QuadricFit, ARolledSheetIsCylindricalAndAPlaneFlat) {
  const double r = 0.3;  // rolled without stretching: the paper's x runs round the roll
  const LaidPaper roll = lay(
      [&](double u, double v) { return Vec3(r * std::sin(u / r), v, r * (1 - std::cos(u / r))); });
  const QuadricFit q = fit_quadric(roll.x, roll.paper);
  EXPECT_NEAR(q.k1 * r, 1.0, 0.03);
  EXPECT_NEAR(q.k2 * r, 0.0, 1e-9);
  EXPECT_EQ(q.classification, "cylindrical");
  const LaidPaper plane =
      lay([](double u, double v) { return Vec3(u, 0.6 * v, 0.3 * u + 0.2 * v); });
  const QuadricFit p = fit_quadric(plane.x, plane.paper);
  EXPECT_NEAR(p.k1, 0.0, 1e-9);
  EXPECT_EQ(p.classification, "flat");
}

TEST(QuadricFit, ASheetRolledNearlyShutIsFolded) {
  // Rolled round 90 % of a circle: no quadric describes it, and the fit says so.
  const double r = kPaperSide / (2.0 * std::numbers::pi * 0.9);
  const LaidPaper roll = lay(
      [&](double u, double v) { return Vec3(r * std::sin(u / r), v, r * (1 - std::cos(u / r))); });
  const QuadricFit q = fit_quadric(roll.x, roll.paper);
  ASSERT_TRUE(q.valid);
  EXPECT_EQ(q.classification, "folded");
}

TEST(QuadricFit, MovingTheFormRigidlyChangesNothing) {
  const LaidPaper l =
      lay([](double u, double v) { return Vec3(u, v, 2.0 * u * u - 0.5 * v * v + u * v); });
  const QuadricFit q = fit_quadric(l.x, l.paper);
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(2.1, Vec3::UnitX()))
          .toRotationMatrix();
  const Points moved = (turn * l.x).colwise() + Vec3(0.3, -1.0, 2.0);
  const QuadricFit m = fit_quadric(moved, l.paper);
  EXPECT_NEAR(m.k1, q.k1, 1e-9 * std::abs(q.k1));
  EXPECT_NEAR(m.k2, q.k2, 1e-9 * std::abs(q.k1));
  EXPECT_EQ(m.classification, q.classification);
}

TEST(QuadricFit, AWrinkledBowlIsABowl) {
  // The sphere of radius 0.4 m with wrinkles 40 mm apart and 1 mm high along its normal: the
  // fit keeps the bowl (within 5 %) and the wrinkles show as its rms (1 mm / 2 / sqrt 2 = 0.35).
  // (The grid's 10 mm spacing samples each wrinkle four times.)
  const double r = 0.4;
  const LaidPaper l = lay([&](double u, double v) {
    const Vec3 p = on_sphere(u, v, r);
    const Vec3 n = (Vec3(0, 0, r) - p).normalized();
    return Vec3(p + 0.5e-3 * std::sin(2 * std::numbers::pi * (u + 0.01) / 0.04) * n);
  });
  const QuadricFit q = fit_quadric(l.x, l.paper);
  EXPECT_NEAR(q.k1 * r, 1.0, 0.05);
  EXPECT_NEAR(q.k2 * r, 1.0, 0.05);
  EXPECT_EQ(q.classification, "synclastic");
  EXPECT_NEAR(q.rms, 0.5e-3 / std::sqrt(2.0), 0.1e-3);
}

TEST(QuadricFit, TooFewOrCollinearParticlesGiveNoFit) {
  EXPECT_FALSE(fit_quadric(Points::Random(3, 5), Points::Random(3, 5)).valid);
  Points line(3, 10);
  for (int i = 0; i < 10; ++i) line.col(i) = Vec3(i, 2.0 * i, 0.0);
  EXPECT_FALSE(fit_quadric(Points::Random(3, 10), line).valid);
  EXPECT_FALSE(fit_quadric(Points::Random(3, 10), Points::Random(3, 9)).valid);
}

TEST(QuadricFit, ClassificationThresholds) {
  EXPECT_EQ(classify_quadric(0.049, 0.049, 1.0), "flat");
  EXPECT_EQ(classify_quadric(1.0, 0.24, 1.0), "cylindrical");
  EXPECT_EQ(classify_quadric(1.0, -0.24, 1.0), "cylindrical");
  EXPECT_EQ(classify_quadric(1.0, 0.26, 1.0), "synclastic");
  EXPECT_EQ(classify_quadric(1.0, -0.26, 1.0), "anticlastic");
}

}  // namespace
}  // namespace membra
