#include "membra/model/partial_cover.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace membra {
namespace partial_cover_test {
namespace {

// A 100 x 100 mm square in 2 mm cells, each cut along alternating diagonals, its vertices
// jittered off the grid lines (so that no band edge runs along a row of them by chance).
struct Mesh {
  Sheet sheet;
  Points x;
};

Mesh square_mesh(bool jitter) {
  const int n = 51;
  Mesh m;
  m.x.resize(3, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double dx = jitter ? 3e-4 * std::sin(1.7 * i + 2.3 * j) : 0.0;
      const double dy = jitter ? 3e-4 * std::cos(2.9 * i - 1.1 * j) : 0.0;
      m.x.col(j * n + i) = Vec3(0.002 * i + dx, 0.002 * j + dy, 0.0);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if ((i + j) % 2 == 0)
        m.sheet.triangles.push_back({a, b, d}), m.sheet.triangles.push_back({a, d, c});
      else
        m.sheet.triangles.push_back({a, b, c}), m.sheet.triangles.push_back({b, d, c});
    }
  return m;
}

// Triangles with corners on both sides of the line through p along u, farther than `margin`.
int across_line(const Mesh& m, const Vec2& p, const Vec2& u, double margin) {
  const Vec2 normal = Vec2(-u.y(), u.x()).normalized();
  int count = 0;
  for (const Triangle& t : m.sheet.triangles) {
    bool below = false, above = false;
    for (const int v : t) {
      const double d = (m.x.col(v).head<2>() - p).dot(normal);
      below = below || d < -margin;
      above = above || d > margin;
    }
    count += below && above;
  }
  return count;
}

// An oblique band 30 mm wide across the square: its edges are straight, so a triangle lies
// across the outline exactly when its corners lie on both sides of one edge (a polygon's field
// is the distance to its nearest edge, linear along each).
TEST(PartialCover, AnObliqueBandIsCrossedWhereItsEdgesCrossTriangles) {
  const Mesh m = square_mesh(true);
  const Vec2 u = Vec2(1.0, 0.37).normalized(), normal(-u.y(), u.x());
  const Vec2 p1(0.0, 0.030), p2 = p1 + 0.030 * normal;
  const PatternPtr band = make_polygon({p1 - 0.5 * u, p1 + 0.5 * u, p2 + 0.5 * u, p2 - 0.5 * u});
  const double margin = 4e-5;
  const int expected = across_line(m, p1, u, margin) + across_line(m, p2, u, margin);
  EXPECT_GT(expected, 100);  // two edges of ~107 mm across 2 mm cells
  EXPECT_EQ(triangles_across(m.sheet, m.x, *band, margin), expected);
}

// A band whose edges run along rows of vertices is followed by the mesh: no triangle across.
TEST(PartialCover, AMeshThatFollowsTheOutlineHasNoneAcross) {
  const Mesh m = square_mesh(false);
  const PatternPtr band =
      make_polygon({{-0.01, 0.020}, {0.11, 0.020}, {0.11, 0.060}, {-0.01, 0.060}});
  EXPECT_EQ(triangles_across(m.sheet, m.x, *band, 4e-5), 0);
  // Moved off the rows by a tenth of a cell, each edge crosses its row of 100 triangles.
  const PatternPtr moved =
      make_polygon({{-0.01, 0.0202}, {0.11, 0.0202}, {0.11, 0.0602}, {-0.01, 0.0602}});
  EXPECT_EQ(triangles_across(m.sheet, m.x, *moved, 4e-5), 200);
}

// A black-and-white image of a disk in pixels of 0.05 mm (its field, the grey level times the
// pixel, stays within 0.025 mm of zero: read as it is, no point would be clearly on either side).
// Its outline, the pixels' staircase, lies within a pixel of the circle: a triangle with corners
// farther than that on both sides is across it, one whose points all lie farther from the circle
// than a pixel and the margin on one side is not.
TEST(PartialCover, AFineImageMasksOutlineIsReadAsADistance) {
  const Mesh m = square_mesh(true);
  const int w = 2000;
  const double pixel = 0.1 / w, r = 0.030;
  const Vec2 centre(0.05, 0.05);
  std::vector<float> grey(static_cast<size_t>(w) * w);
  for (int row = 0; row < w; ++row)
    for (int col = 0; col < w; ++col) {
      const Vec2 p((col + 0.5) * pixel, 0.1 - (row + 0.5) * pixel);  // row 0 at the top
      grey[static_cast<size_t>(row) * w + col] = (p - centre).norm() < r ? 0.0f : 1.0f;
    }
  const PatternPtr disk = make_raster(grey, w, w, Vec2::Zero(), Vec2(0.1, 0.1), 0.5, false);
  const double margin = 4e-5, slack = 2.0 * pixel + margin;
  int surely = 0, maybe = 0;
  for (const Triangle& t : m.sheet.triangles) {
    double lo = 1.0, hi = -1.0;
    for (const int v : t) {
      const double d = (m.x.col(v).head<2>() - centre).norm() - r;
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    surely += lo < -slack && hi > slack;
    // The circle's distance changes by at most an edge along the triangle.
    const double edge =
        (m.x.col(t[0]) - m.x.col(t[1])).norm() + (m.x.col(t[1]) - m.x.col(t[2])).norm();
    maybe += lo < slack + edge && hi > -slack - edge;
  }
  const int across = triangles_across(m.sheet, m.x, *disk, margin);
  EXPECT_GT(surely, 100);  // a circle of 188 mm across 2 mm cells
  EXPECT_GE(across, surely);
  EXPECT_LE(across, maybe);
}

}  // namespace
}  // namespace partial_cover_test
}  // namespace membra
