// Where a form passes through itself (measure/self_intersection.hpp): crossing triangles found,
// touching neighbours and separate layers not.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/measure/self_intersection.hpp"

namespace membra {
namespace self_intersection {
namespace {

// Two triangles: one in the plane z = 0, the other standing across it (crossing) or lifted
// above it (apart).
TEST(SelfIntersection, TwoTrianglesCrossOrNot) {
  Points x(3, 6);
  x.col(0) = Vec3(0, 0, 0), x.col(1) = Vec3(1, 0, 0), x.col(2) = Vec3(0, 1, 0);
  x.col(3) = Vec3(0.2, 0.2, -0.5), x.col(4) = Vec3(0.3, 0.2, 0.5), x.col(5) = Vec3(0.25, 0.6, 0.5);
  const std::vector<Triangle> tris = {Triangle(0, 1, 2), Triangle(3, 4, 5)};
  const SelfIntersection crossing = self_intersections(x, tris);
  EXPECT_EQ(crossing.pairs, 1);
  EXPECT_EQ(crossing.triangles, (std::vector<int>{0, 1}));
  x.row(2).tail(3).array() += 0.6;  // all of the second triangle above the plane
  EXPECT_EQ(self_intersections(x, tris).pairs, 0);
}

// Not-finite positions are not checked (a diverged state); two huge triangles among small ones,
// which alone would span millions of cells, are still checked, on coarser cells.
TEST(SelfIntersection, NaNsAreSkippedAndHugeTrianglesStillChecked) {
  Points x(3, 6);
  x.col(0) = Vec3(0, 0, 0), x.col(1) = Vec3(1, 0, 0), x.col(2) = Vec3(0, 1, 0);
  x.col(3) = Vec3(0.2, 0.2, -0.5), x.col(4) = Vec3(0.8, 0.2, 0.5), x.col(5) = Vec3(0.25, 0.6, 0.5);
  std::vector<Triangle> tris = {Triangle(0, 1, 2), Triangle(3, 4, 5)};
  // A hundred thousand tiny triangles far off, 1 um across: the mean size makes cells of about
  // 40 um, and the standing triangle's box (0.6 x 0.4 x 1 m) would span 4e12 of them.
  const int tiny = 100000;
  x.conservativeResize(3, 6 + 3 * tiny);
  for (int k = 0; k < tiny; ++k) {
    const int first = 6 + 3 * k;
    const Vec3 at(5.0 + 1e-5 * k, 5.0, 5.0);
    x.col(first) = at, x.col(first + 1) = at + Vec3(1e-6, 0, 0);
    x.col(first + 2) = at + Vec3(0, 1e-6, 0);
    tris.emplace_back(first, first + 1, first + 2);
  }
  EXPECT_EQ(self_intersections(x, tris).pairs, 1);
  x(0, 4) = std::nan("");
  EXPECT_EQ(self_intersections(x, tris).pairs, 0);
}

// A sheet of n x n nodes, 100 x 100 mm, each node placed by `shape` from its paper position.
struct Surface {
  Points x;
  std::vector<Triangle> tris;
};

Surface sheet(int n, const std::function<Vec3(double, double)>& shape) {
  const GridSheet g(GridSpec{0.1, 0.1, n, n});
  Surface s;
  s.x.resize(3, g.num_particles());
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    s.x.col(p) = shape(q.x(), q.y());
  }
  s.tris = triangulate(g);
  return s;
}

// A flat sheet, a bowl and a sheet rolled once round into a tube 2 mm short of closing: the
// neighbours touch along edges and corners, nothing crosses.
TEST(SelfIntersection, SmoothFormsAndAnOpenRollDoNotCross) {
  const Surface flat = sheet(21, [](double u, double v) { return Vec3(u, v, 0); });
  EXPECT_EQ(self_intersections(flat.x, flat.tris).pairs, 0);
  const Surface bowl = sheet(21, [](double u, double v) {
    return Vec3(u, v, 3.0 * ((u - 0.05) * (u - 0.05) + (v - 0.05) * (v - 0.05)));
  });
  EXPECT_EQ(self_intersections(bowl.x, bowl.tris).pairs, 0);
  const double r = 0.102 / (2.0 * std::acos(-1.0));  // a tube of 102 mm round
  const Surface tube = sheet(41, [&](double u, double v) {
    return Vec3(r * std::sin(u / r), v, r * (1.0 - std::cos(u / r)));
  });
  EXPECT_EQ(self_intersections(tube.x, tube.tris).pairs, 0);
}

// The same sheet rolled one and a half times round. As a spiral whose radius grows 2 mm a turn,
// the outer half turn lies outside the inner one and nothing crosses; with a radius that first
// grows and then shrinks (r0 + 2 mm sin(a / 3) at angle a) the last half turn passes through the
// first a quarter turn in, along the whole width of the sheet.
TEST(SelfIntersection, ARollOverItselfCrossesWhereItsTurnsMeet) {
  const double pi = std::acos(-1.0), r0 = 0.1 / (2.0 * pi * 1.5);
  const auto roll = [&](const std::function<double(double)>& radius) {
    return [=](double u, double v) {
      const double a = u / r0, r = radius(a);
      return Vec3(r * std::sin(a), v, r0 - r * std::cos(a));
    };
  };
  const Surface spiral = sheet(61, roll([&](double a) { return r0 + 0.002 * a / (2.0 * pi); }));
  EXPECT_EQ(self_intersections(spiral.x, spiral.tris).pairs, 0);
  const Surface through = sheet(61, roll([&](double a) { return r0 + 0.002 * std::sin(a / 3); }));
  const SelfIntersection si = self_intersections(through.x, through.tris);
  EXPECT_GE(si.pairs, 60);  // at least one pair per row of cells across the width
  EXPECT_GE(si.triangles.size(), 60u);
  // Where they cross: a quarter turn round the roll, on its side (x = r, z = r0), mid-width.
  EXPECT_NEAR(si.at.x(), r0 + 0.002 * std::sin(pi / 6), 0.003);
  EXPECT_NEAR(si.at.y(), 0.05, 0.005);
  EXPECT_NEAR(si.at.z(), r0, 0.003);
}

}  // namespace
}  // namespace self_intersection
}  // namespace membra
