// The per-element projection onto the positive semi-definite cone (model/psd_projection.hpp).
#include <gtest/gtest.h>

#include <random>

#include "membra/model/psd_projection.hpp"

namespace psd_projection_test {

using membra::project_psd;

using Mat = Eigen::Matrix<double, 15, 15>;

Mat random_symmetric(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Mat a;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) a(i, j) = g(rng);
  return 0.5 * (a + a.transpose());
}

// The closest PSD matrix to m in the Frobenius norm is m's positive part m+ (m = m+ - m-, both
// positive semi-definite, m+ m- = 0). So: p is positive semi-definite, so is p - m (= m-), and
// p (p - m) = 0.
TEST(PsdProjection, AnIndefiniteBlockLosesItsNegativeEigenvaluesOnly) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat m = random_symmetric(rng);
    const Mat p = project_psd(m);
    const double scale = m.norm();
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat>(p).eigenvalues().minCoeff(), -1e-12 * scale);
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat>(Mat(p - m)).eigenvalues().minCoeff(),
              -1e-12 * scale);
    EXPECT_LE((p * (p - m)).norm(), 1e-12 * scale * scale);
    EXPECT_GT((p - m).norm(), 0.1 * scale);  // a random block is indefinite: something went
  }
}

// A positive definite block comes back bit for bit; a singular positive semi-definite one (rank
// 3, as a shell triangle's at rest, J^T A J) to round-off.
TEST(PsdProjection, APositiveSemiDefiniteBlockComesBackUnchanged) {
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Matrix<double, 3, 15> j;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 15; ++c) j(r, c) = g(rng);
    const Mat singular = j.transpose() * j;
    const Mat a = random_symmetric(rng);
    const Mat definite = a * a.transpose() + Mat::Identity();
    EXPECT_LE((project_psd(singular) - singular).norm(), 1e-12 * singular.norm());
    EXPECT_EQ(project_psd(definite), definite);
  }
  EXPECT_EQ(project_psd(Mat(Mat::Zero())), Mat::Zero());
}

}  // namespace psd_projection_test
