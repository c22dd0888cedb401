// Window sums over the paper: on a grid's rows and on scattered particles (a continuum mesh's
// vertices, put in bands), each equal to the sum over every particle inside the window.
#include "membra/measure/paper_rows.hpp"

#include <gtest/gtest.h>

#include <random>

namespace membra {
namespace paper_rows_test {

// The sum by visiting every particle, with the rows' test: |y - cy| <= r and |x - cx| <= chord.
Eigen::VectorXd brute_sum(const Points& paper, const Eigen::MatrixXd& values, const Vec2& c,
                          double r) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(values.rows());
  for (Eigen::Index p = 0; p < paper.cols(); ++p) {
    const double dy = paper(1, p) - c.y();
    if (dy < -r || dy > r) continue;
    const double w = std::sqrt(std::max(0.0, r * r - dy * dy));
    if (paper(0, p) >= c.x() - w && paper(0, p) <= c.x() + w) sum += values.col(p);
  }
  return sum;
}

void expect_windows_match(const Points& paper, std::mt19937_64& rng, const char* what) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::MatrixXd values(2, paper.cols());
  for (Eigen::Index p = 0; p < paper.cols(); ++p) values.col(p) << 1.0, u(rng) - 0.5;
  const PaperRows rows(paper, values);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec2 c(1.2 * u(rng) - 0.1, 1.2 * u(rng) - 0.1);  // some windows reach past the sheet
    const double r = trial % 3 == 0 ? 0.5 * u(rng) : 0.08 * u(rng);
    const Eigen::VectorXd expected = brute_sum(paper, values, c, r);
    const Eigen::VectorXd got = rows.sum_within(c, r);
    ASSERT_EQ(got[0], expected[0]) << what << ": particles counted, window " << trial;
    ASSERT_NEAR(got[1], expected[1], 1e-9) << what << ": window " << trial;
  }
}

TEST(PaperRows, AGridsRowsAndScatteredParticlesSumEveryParticleInTheWindow) {
  std::mt19937_64 rng(11);
  Points grid(3, 41 * 41);
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) grid.col(j * 41 + i) = Vec3(i / 40.0, j / 40.0, 0.0);
  expect_windows_match(grid, rng, "grid");
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points scattered(3, 5000);
  for (Eigen::Index p = 0; p < scattered.cols(); ++p) scattered.col(p) = Vec3(u(rng), u(rng), 0.0);
  for (Eigen::Index p = 0; p < 40; ++p) scattered(1, p) = 0.5;  // a straight edge shares one y
  expect_windows_match(scattered, rng, "scattered");
}

}  // namespace paper_rows_test
}  // namespace membra
