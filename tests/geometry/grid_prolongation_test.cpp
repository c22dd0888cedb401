#include "membra/geometry/grid_prolongation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace membra {
namespace {

// Positions that are an affine function of the paper position: bilinear interpolation must
// carry them over exactly, and so a flat or uniformly stretched sheet stays what it was.
Points affine_positions(const GridSheet& g) {
  Points x(3, g.num_particles());
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    x.col(p) = Vec3(1.5 * q.x() + 0.2 * q.y() + 0.01, -0.3 * q.x() + 1.1 * q.y(), 0.4 * q.x());
  }
  return x;
}

TEST(GridProlongation, CarriesAffineFormsOverExactly) {
  const GridSheet coarse(GridSpec{0.2, 0.1, 9, 5}), fine(GridSpec{0.2, 0.1, 17, 9});
  const Points x = prolongate(coarse, affine_positions(coarse), fine);
  EXPECT_LT((x - affine_positions(fine)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(GridProlongation, InterpolatesBetweenCoarseNodes) {
  // A quadratic height: the fine nodes halfway between coarse ones take the mean of their two
  // (or four) coarse neighbours, the shared nodes keep their values.
  const GridSheet coarse(GridSpec{0.1, 0.1, 3, 3}), fine(GridSpec{0.1, 0.1, 5, 5});
  Points xc = affine_positions(coarse);
  for (int p = 0; p < coarse.num_particles(); ++p) {
    const auto [i, j] = coarse.node(p);
    xc(2, p) = i * i + 10.0 * j;
  }
  const Points x = prolongate(coarse, xc, fine);
  EXPECT_DOUBLE_EQ(x(2, fine.particle(4, 0)), 4.0);            // coarse node (2, 0)
  EXPECT_DOUBLE_EQ(x(2, fine.particle(3, 0)), 0.5 * (1 + 4));  // between (1, 0) and (2, 0)
  EXPECT_DOUBLE_EQ(x(2, fine.particle(1, 1)), 0.25 * (0 + 1 + 10 + 11));
}

TEST(GridProlongation, SharesTheWeightAmongThePresentCoarseNodes) {
  // A disk: the coarse grid lacks the corners of cells on the rim; a fine node there takes the
  // present nodes' values, never a missing one's (which would be zero or garbage).
  const auto disk = [](double x, double y) {
    return std::hypot(x - 0.05, y - 0.05) <= 0.05 + 1e-12;
  };
  const GridSheet coarse(GridSpec{0.1, 0.1, 9, 9}, disk), fine(GridSpec{0.1, 0.1, 17, 17}, disk);
  Points xc = Points::Zero(3, coarse.num_particles());
  xc.row(2).setConstant(7.0);  // every coarse particle at height 7
  const Points x = prolongate(coarse, xc, fine);
  EXPECT_EQ(x.cols(), fine.num_particles());
  EXPECT_LT((x.row(2).array() - 7.0).abs().maxCoeff(), 1e-12);
}

TEST(GridProlongation, RefusesGridsOfDifferentSheets) {
  const GridSheet a(GridSpec{0.2, 0.2, 5, 5}), b(GridSpec{0.3, 0.2, 9, 9});
  EXPECT_THROW(prolongate(a, Points::Zero(3, a.num_particles()), b), std::invalid_argument);
  EXPECT_THROW(prolongate(a, Points::Zero(3, 3), a), std::invalid_argument);
}

}  // namespace
}  // namespace membra
