// Edge extrapolation: exact on the fields it assumes, and refused where it cannot work.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/measure/hole_edge.hpp"

namespace membra {
namespace {

TEST(HoleEdge, SamplingIsBilinearAndStopsAtMissingParticles) {
  const GridSheet g({0.01, 0.01, 11, 11});
  std::vector<double> f(static_cast<size_t>(g.num_particles()));
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    f[p] = 2.0 + 3.0 * i - 0.5 * j;  // linear: bilinear interpolation is exact
  }
  EXPECT_NEAR(*sample_field(g, f, Vec2(0.00437, 0.00612)), 2.0 + 3.0 * 4.37 - 0.5 * 6.12, 1e-12);
  EXPECT_FALSE(sample_field(g, f, Vec2(0.0105, 0.005)));  // off the sheet
  EXPECT_FALSE(sample_field(g, f, Vec2(-1e-4, 0.005)));
}

// A field that is Kirsch's form around a circle: recovered exactly at the edge.
TEST(HoleEdge, RecoversAQuadraticInRSquaredOverRSquaredExactly) {
  const int n = 101;
  const double h = 1e-3, radius = 0.012;
  const Vec2 c(0.05, 0.05);
  const GridSheet g({(n - 1) * h, (n - 1) * h, n, n});
  std::vector<double> f(static_cast<size_t>(g.num_particles()));
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const double r = (g.position(i, j) - c).norm(), u = radius * radius / (r * r);
    f[p] = 0.5 * (2 + u + 3 * u * u);  // Kirsch above the hole: 3 at the edge
  }
  // Exact at grid nodes; between them bilinear sampling of the curved field errs by ~h^2 f''/8
  // (~0.1 %), which the extrapolation over 3-8 spacings amplifies about tenfold.
  EXPECT_NEAR(*edge_value(g, f, c, radius, Vec2(1, 0)), 3.0, 1e-9);
  for (double t : {0.7, 1.5708, 4.0})
    EXPECT_NEAR(*edge_value(g, f, c, radius, Vec2(std::cos(t), std::sin(t))), 3.0, 0.05) << t;
}

TEST(HoleEdge, SmallHolesAreNotExtrapolated) {
  const GridSheet g({0.1, 0.1, 101, 101});
  const std::vector<double> f(static_cast<size_t>(g.num_particles()), 1.0);
  // Removed particles within 3 spacings of the centre: radius about 3.5 spacings.
  std::vector<Vec2> removed;
  for (int i = 47; i <= 53; ++i)
    for (int j = 47; j <= 53; ++j)
      if ((i - 50) * (i - 50) + (j - 50) * (j - 50) <= 9) removed.emplace_back(i * 1e-3, j * 1e-3);
  const HoleEdge small = hole_edge(g, f, removed);
  EXPECT_FALSE(small.valid);
  EXPECT_GT(small.radius, 3e-3);
  EXPECT_LT(small.radius, 6e-3);
  // The same constant field around a hole of 10 spacings: valid, and the constant.
  removed.clear();
  for (int i = 35; i <= 65; ++i)
    for (int j = 35; j <= 65; ++j)
      if ((i - 50) * (i - 50) + (j - 50) * (j - 50) <= 100)
        removed.emplace_back(i * 1e-3, j * 1e-3);
  const HoleEdge big = hole_edge(g, f, removed);
  ASSERT_TRUE(big.valid);
  EXPECT_NEAR(big.value, 1.0, 1e-9);
  EXPECT_NEAR(big.centre.x(), 0.05, 1e-12);
  // Cells with a removed corner go: the hole reaches about half a cell diagonal past the nodes.
  EXPECT_NEAR(big.radius / 1e-3, 10.6, 0.3);
}

}  // namespace
}  // namespace membra
