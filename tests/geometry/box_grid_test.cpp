// The box grid, the broad phase of the self-intersection check and of self-contact: it finds the
// same overlapping pairs as a test of every pair, each once, on boxes of even size, on a few
// huge slivers that coarsen its cells, and beside boxes that are not finite.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "membra/geometry/box_grid.hpp"

namespace membra {
namespace box_grid_test {
namespace {

std::vector<Eigen::AlignedBox3d> random_boxes(int n, double span, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(-span, span), side(0.0, size);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < n; ++i) {
    const Vec3 lo(at(rng), at(rng), at(rng));
    boxes.emplace_back(lo, lo + Vec3(side(rng), side(rng), side(rng)));
  }
  return boxes;
}

std::set<std::pair<int, int>> brute_force_pairs(const std::vector<Eigen::AlignedBox3d>& boxes) {
  std::set<std::pair<int, int>> out;
  for (int a = 0; a < static_cast<int>(boxes.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(boxes.size()); ++b)
      if (!boxes[static_cast<size_t>(a)].isEmpty() &&
          boxes[static_cast<size_t>(a)].intersects(boxes[static_cast<size_t>(b)]))
        out.insert({a, b});
  return out;
}

// Every overlapping pair exactly once, listed in order, through the grid.
std::set<std::pair<int, int>> grid_pairs(const BoxGrid& grid) {
  std::set<std::pair<int, int>> out;
  grid.overlapping_pairs([&](int a, int b) {
    EXPECT_LT(a, b);
    EXPECT_TRUE(out.insert({a, b}).second) << "pair " << a << ", " << b << " came twice";
  });
  return out;
}

TEST(BoxGrid, FindsEveryOverlappingPairOnceAsATestOfEveryPairDoes) {
  const auto boxes = random_boxes(600, 1.0, 0.3, 1);
  const auto expected = brute_force_pairs(boxes);
  ASSERT_GT(expected.size(), 200u);
  for (double cell : {0.01, 0.1, 1.0, 50.0}) {
    const BoxGrid grid(boxes, cell);
    EXPECT_EQ(grid_pairs(grid), expected) << "cell " << cell;
  }
}

TEST(BoxGrid, AQueryMeetsEveryBoxItOverlapsAndNoneFarOutside) {
  const auto boxes = random_boxes(400, 1.0, 0.1, 2);
  const BoxGrid grid(boxes, BoxGrid::mean_size(boxes));
  for (const auto& query : random_boxes(50, 1.5, 0.3, 3)) {
    std::set<int> found;
    grid.overlapping(query, [&](int b) { found.insert(b); });
    for (int b = 0; b < static_cast<int>(boxes.size()); ++b)
      if (boxes[static_cast<size_t>(b)].intersects(query)) {
        EXPECT_TRUE(found.count(b)) << b;
      }
  }
  int far = 0;
  const Eigen::AlignedBox3d outside(Vec3(5, 5, 5), Vec3(6, 6, 6));
  grid.overlapping(outside, [&](int) { ++far; });
  grid.overlapping(Eigen::AlignedBox3d(Vec3::Constant(-1e300), Vec3::Constant(-1e299)),
                   [&](int) { ++far; });
  EXPECT_EQ(far, 0);
  // A query reaching far past the grid on every side is clipped to it: every box comes.
  std::set<int> all;
  grid.overlapping(Eigen::AlignedBox3d(Vec3::Constant(-1e300), Vec3::Constant(1e300)),
                   [&](int b) { all.insert(b); });
  EXPECT_EQ(all.size(), boxes.size());
}

TEST(BoxGrid, AFewHugeSliversCoarsenTheCellsAndChangeNoPair) {
  auto boxes = random_boxes(300, 1.0, 0.002, 4);
  const double small = BoxGrid::mean_size(boxes);
  // Three slivers across the whole field: at the small boxes' size each would meet millions
  // of cells.
  for (int k = 0; k < 3; ++k)
    boxes.emplace_back(Vec3(-1.0, -1.0, -1.0 + 0.5 * k), Vec3(1.0, 1.0, -0.9 + 0.5 * k));
  const BoxGrid grid(boxes, small);
  EXPECT_GT(grid.cell(), 2.0 * small);
  const auto expected = brute_force_pairs(boxes);
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(grid_pairs(grid), expected);
}

TEST(BoxGrid, BoxesThatAreNotFiniteAreInNoCell) {
  auto boxes = random_boxes(50, 1.0, 0.5, 5);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  boxes[7] = Eigen::AlignedBox3d(Vec3(nan, 0, 0), Vec3(nan, 1, 1));
  boxes[9] = Eigen::AlignedBox3d(Vec3(0, 0, 0), Vec3(inf, 1, 1));
  // The rest keep their pairs: an infinite box does not stretch the grid over everything.
  auto finite = boxes;
  finite[7].setEmpty();
  finite[9].setEmpty();
  const auto expected = brute_force_pairs(finite);
  ASSERT_GT(expected.size(), 5u);
  const BoxGrid grid(boxes, 0.3);
  EXPECT_EQ(grid_pairs(grid), expected);
  const Eigen::AlignedBox3d empty;
  EXPECT_EQ(BoxGrid::mean_size({Eigen::AlignedBox3d(Vec3::Zero(), Vec3(2, 1, 1)), empty, boxes[9],
                                boxes[7], Eigen::AlignedBox3d(Vec3::Zero(), Vec3(1, 4, 1))}),
            3.0);
  int met = 0;
  const BoxGrid none({}, 1.0);
  none.overlapping(Eigen::AlignedBox3d(Vec3::Zero(), Vec3::Ones()), [&](int) { ++met; });
  none.overlapping_pairs([&](int, int) { ++met; });
  EXPECT_EQ(met, 0);
}

// Cells far smaller than the field would not fit a key's 21 bits per axis: they are made at
// least 1/2 000 000 of the field, and tiny boxes at its two ends still pair as they should.
TEST(BoxGrid, TinyCellsOverAWideFieldKeepTheirPairs) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (double at : {0.0, 1000.0, 2.0e-7, 1000.0 + 2.0e-7})
    boxes.emplace_back(Vec3::Constant(at), Vec3::Constant(at + 1e-6));
  boxes.emplace_back(Vec3(500.0, 0.0, 0.0), Vec3(500.0 + 1e-6, 1e-6, 1e-6));
  const BoxGrid grid(boxes, 1e-9);
  EXPECT_GE(grid.cell(), 1000.0 / 2.0e6);
  const std::set<std::pair<int, int>> expected{{0, 2}, {1, 3}};
  EXPECT_EQ(brute_force_pairs(boxes), expected);
  EXPECT_EQ(grid_pairs(grid), expected);
  // And boxes farther apart than a double spans still pair within one cell.
  const std::vector<Eigen::AlignedBox3d> far{
      Eigen::AlignedBox3d(Vec3::Constant(-1e308), Vec3::Constant(-0.9e308)),
      Eigen::AlignedBox3d(Vec3::Constant(0.9e308), Vec3::Constant(1e308)),
      Eigen::AlignedBox3d(Vec3::Constant(0.95e308), Vec3::Constant(1e308))};
  const BoxGrid wide(far, 1.0);
  EXPECT_EQ(grid_pairs(wide), (std::set<std::pair<int, int>>{{1, 2}}));
  std::set<int> met;
  wide.overlapping(Eigen::AlignedBox3d(Vec3::Constant(0.96e308), Vec3::Constant(0.97e308)),
                   [&](int b) { met.insert(b); });
  EXPECT_EQ(met, (std::set<int>{0, 1, 2}));  // one cell: every box is a candidate
  const double nan = std::numeric_limits<double>::quiet_NaN();
  wide.overlapping(Eigen::AlignedBox3d(Vec3::Constant(nan), Vec3::Constant(nan)),
                   [&](int b) { met.insert(b + 10); });
  EXPECT_EQ(met.size(), 3u);
}

}  // namespace
}  // namespace box_grid_test
}  // namespace membra
