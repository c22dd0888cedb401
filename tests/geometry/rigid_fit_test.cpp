#include "membra/geometry/rigid_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <stdexcept>

namespace membra {
namespace {

// A scattered, non-planar set of points (a rigid fit needs three not on a line).
Points scattered(int n) {
  Points p(3, n);
  for (int i = 0; i < n; ++i)
    p.col(i) = Vec3(std::sin(1.3 * i), std::cos(0.7 * i + 0.2), 0.3 * std::sin(2.1 * i + 1.0));
  return p;
}

// A known motion is recovered to round-off, at the scale of a sheet in metres and a million
// times larger.
TEST(RigidFit, RecoversAKnownMotion) {
  for (double scale : {1e-3, 1.0, 1e3}) {
    const Points p = scattered(20) * scale;
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(0.9, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
    const Vec3 t = Vec3(0.3, -0.1, 2.0) * scale;
    const Points q = (r * p).colwise() + t;
    const RigidMotion m = rigid_fit(p, q);
    EXPECT_LT((m.rotation - r).norm(), 1e-12) << scale;
    EXPECT_LT((m.translation - t).norm(), 1e-12 * scale) << scale;
    EXPECT_NEAR(m.rotation.determinant(), 1.0, 1e-12);
  }
}

// Weights: points of weight zero do not pull the fit, however far they lie.
TEST(RigidFit, ZeroWeightsAreIgnored) {
  const Points p = scattered(12);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(-0.4, Vec3::UnitZ()).toRotationMatrix();
  Points q = r * p;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(12);
  q.col(3) += Vec3(5.0, 5.0, 5.0);
  w[3] = 0.0;
  EXPECT_LT((rigid_fit(p, q, w).rotation - r).norm(), 1e-12);
  EXPECT_GT((rigid_fit(p, q).rotation - r).norm(), 1e-3);  // with it, the outlier pulls
}

// A mirror image is not a rigid motion: the fit stays a proper rotation.
TEST(RigidFit, NeverMirrors) {
  const Points p = scattered(15);
  Points q = p;
  q.row(2) *= -1.0;
  EXPECT_NEAR(rigid_fit(p, q).rotation.determinant(), 1.0, 1e-12);
  EXPECT_NEAR(kabsch_rotation(p * q.transpose()).determinant(), 1.0, 1e-12);
}

TEST(RigidFit, RefusesMismatchedSets) {
  EXPECT_THROW(rigid_fit(scattered(4), scattered(5)), std::invalid_argument);
  EXPECT_THROW(rigid_fit(Points(3, 0), Points(3, 0)), std::invalid_argument);
  EXPECT_THROW(rigid_fit(scattered(4), scattered(4), Eigen::VectorXd::Zero(4)),
               std::invalid_argument);
}

}  // namespace
}  // namespace membra
