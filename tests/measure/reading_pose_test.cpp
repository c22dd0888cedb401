// The reading pose: a bowl turned upside down and tilted comes back opening upward, centred, on
// the table; a saddle's axes come out along x and y.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "membra/measure/reading_pose.hpp"

namespace membra {
namespace {

// A quadric z = (x^2 / r1 + y^2 / r2) / 2 sampled over a 0.2 x 0.1 m paper, then turned by
// `turn` and moved: the paper positions and the form.
void quadric_sheet(double r1, double r2, const Eigen::Matrix3d& turn, Points& paper, Points& x) {
  const int nx = 21, ny = 11;
  paper.resize(3, nx * ny);
  x.resize(3, nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double u = -0.1 + 0.01 * i, v = -0.05 + 0.01 * j;
      paper.col(j * nx + i) = Vec3(u + 0.1, v + 0.05, 0.0);
      const Vec3 p(u, v, 0.5 * (u * u / r1 + v * v / r2));
      x.col(j * nx + i) = turn * p + Vec3(0.3, -0.2, 0.7);
    }
}

Points posed(const Points& x, const Points& paper) {
  const RigidMotion m = reading_pose(x, fit_quadric(x, paper));
  EXPECT_NEAR(m.rotation.determinant(), 1.0, 1e-12);  // a rotation, never a mirror
  return (m.rotation * x).colwise() + m.translation;
}

TEST(ReadingPose, ABowlUpsideDownAndTiltedOpensUpwardOnTheTable) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(2.5, Vec3(0.3, 1.0, 0.2).normalized())).toRotationMatrix();
  Points paper, x;
  quadric_sheet(0.15, 0.25, turn, paper, x);
  const Points y = posed(x, paper);
  const Vec3 lo = y.rowwise().minCoeff(), hi = y.rowwise().maxCoeff();
  EXPECT_NEAR(lo.z(), 0.0, 1e-12);           // on the table
  EXPECT_NEAR(lo.x() + hi.x(), 0.0, 1e-12);  // centred
  EXPECT_NEAR(lo.y() + hi.y(), 0.0, 1e-12);
  const int centre = 5 * 21 + 10, corner = 0;
  EXPECT_NEAR(y(2, centre), 0.0, 1e-12);  // the bottom of the bowl is its lowest point
  EXPECT_GT(y(2, corner), 0.01);          // and its rim rises: it opens upward
  // Its box is the untilted bowl's: the paper's x (0.2 m wide) along x.
  EXPECT_NEAR(hi.z(), 0.5 * (0.01 / 0.15 + 0.0025 / 0.25), 1e-9);
  EXPECT_NEAR(hi.x() - lo.x(), 0.2, 1e-9);
  EXPECT_NEAR(hi.y() - lo.y(), 0.1, 1e-9);
}

TEST(ReadingPose, ASaddlesAxesLieAlongXAndY) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.7, Vec3(0.0, 0.0, 1.0)) * Eigen::AngleAxisd(2.0, Vec3::UnitX()))
          .toRotationMatrix();
  Points paper, x;
  quadric_sheet(0.2, -0.3, turn, paper, x);
  const Points y = posed(x, paper);
  // Along x it rises to the ends, along y it falls: z at the ends of the two middle lines.
  const int mid_row = 5 * 21, mid_col = 10;
  const double x_ends = y(2, mid_row) - y(2, mid_row + 10),
               y_ends = y(2, mid_col) - y(2, mid_row + 10);
  EXPECT_NEAR(x_ends, 0.5 * 0.01 / 0.2, 1e-9);
  EXPECT_NEAR(y_ends, -0.5 * 0.0025 / 0.3, 1e-9);
  // The middle lines run along the axes: the x line has no y spread and the y line no x spread.
  EXPECT_NEAR(y(1, mid_row) - y(1, mid_row + 20), 0.0, 1e-9);
  EXPECT_NEAR(y(0, mid_col) - y(0, 10 * 21 + mid_col), 0.0, 1e-9);
}

}  // namespace
}  // namespace membra
