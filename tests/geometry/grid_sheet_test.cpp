// Grid sheets, masks and triangulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {
namespace {

TEST(GridSheet, FullGridNumbersNodesRowByRow) {
  const GridSheet g({0.2, 0.1, 5, 3});
  EXPECT_EQ(g.num_particles(), 15);
  EXPECT_DOUBLE_EQ(g.hx(), 0.05);
  EXPECT_DOUBLE_EQ(g.hy(), 0.05);
  EXPECT_EQ(g.particle(2, 1), 7);
  EXPECT_EQ(g.node(7), std::make_pair(2, 1));
  EXPECT_EQ(g.particle(5, 0), -1);
  EXPECT_EQ(g.particle(-1, 0), -1);
  EXPECT_NEAR((g.position(4, 2) - Vec2(0.2, 0.1)).norm(), 0.0, 1e-15);
}

TEST(GridSheet, MaskRemovesNodesAndIsolatedNodesAreDropped) {
  // A hole of radius 0.03 m around the centre of a 0.2 m sheet with 0.02 m spacing.
  const auto keep = [](double x, double y) {
    return (x - 0.1) * (x - 0.1) + (y - 0.1) * (y - 0.1) > 0.03 * 0.03;
  };
  const GridSheet g({0.2, 0.2, 11, 11}, keep);
  EXPECT_EQ(g.particle(5, 5), -1);
  EXPECT_FALSE(g.cell_active(4, 4));
  // Nodes within 0.03 m of the centre: (0,0), (+-1,0), (0,+-1), (+-1,+-1) in spacing units.
  EXPECT_EQ(g.num_particles(), 121 - 9);
  // A node alone between masked neighbours belongs to no cell and is dropped.
  const GridSheet lonely({0.2, 0.2, 3, 3}, [](double x, double) { return x < 0.05 || x > 0.15; });
  EXPECT_EQ(lonely.num_particles(), 6);
  EXPECT_EQ(lonely.without_isolated_nodes().num_particles(), 0);
}

TEST(GridSheet, RejectsDegenerateSpecs) {
  EXPECT_THROW(GridSheet({0.2, 0.2, 1, 5}), std::invalid_argument);
  EXPECT_THROW(GridSheet({0.0, 0.2, 5, 5}), std::invalid_argument);
  EXPECT_THROW(GridSheet({0.2, -1.0, 5, 5}), std::invalid_argument);
}

TEST(Triangulation, TwoCounterClockwiseTrianglesPerActiveCell) {
  const GridSheet g({0.3, 0.2, 4, 3});
  const auto tris = triangulate(g);
  ASSERT_EQ(tris.size(), 2u * 3 * 2);
  double area = 0.0;
  for (const auto& t : tris) {
    const Vec2 a = g.position(g.node(t[0]).first, g.node(t[0]).second);
    const Vec2 b = g.position(g.node(t[1]).first, g.node(t[1]).second);
    const Vec2 c = g.position(g.node(t[2]).first, g.node(t[2]).second);
    const double signed_area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    EXPECT_GT(signed_area, 0.0);
    area += signed_area;
  }
  EXPECT_NEAR(area, 0.3 * 0.2, 1e-15);
}

// The boundary of a 7 x 7 grid with its centre node masked out (a hole): the 24 nodes of the
// outline and the 8 around the hole, the same as edge_counts' edges of one triangle; the other
// 16 nodes are inside.
TEST(Triangulation, BoundaryVerticesAreTheOutlineAndTheHolesRim) {
  const GridSheet g({0.6, 0.6, 7, 7}, [](double x, double y) {
    return std::abs(x - 0.3) > 1e-9 || std::abs(y - 0.3) > 1e-9;
  });
  const auto tris = triangulate(g);
  const std::vector<bool> on = boundary_vertices(g.num_particles(), tris);
  std::vector<bool> want(on.size(), false);
  for (const auto& [edge, count] : edge_counts(tris))
    if (count == 1)
      want[static_cast<size_t>(edge.first)] = want[static_cast<size_t>(edge.second)] = true;
  EXPECT_EQ(on, want);
  ASSERT_EQ(on.size(), 48u);
  EXPECT_EQ(std::count(on.begin(), on.end(), true), 24 + 8);
  EXPECT_EQ(edge_key(3, 7), edge_key(7, 3));
  EXPECT_EQ(edge_key(3, 7) >> 32, 3u);
}

}  // namespace
}  // namespace membra
