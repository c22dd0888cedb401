// The triangle locator: every triangle that holds a point is among its candidates, in the mesh's
// order, so a look-up through it finds the same triangle as a scan of all of them.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "membra/geometry/triangle_locator.hpp"

namespace membra {
namespace {

// Barycentric coordinates of p in (a, b, c); none when degenerate.
std::optional<Vec3> weights(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  if (det == 0.0) return std::nullopt;
  const double u = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / det;
  const double v = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / det;
  return Vec3(1.0 - u - v, u, v);
}

// A jittered n x n grid of vertices over [0, 0.15]^2 m, two triangles per cell, the diagonals
// alternating; every triangle counter-clockwise.
struct Mesh {
  Eigen::Matrix2Xd xy;
  std::vector<Triangle> triangles;
};
Mesh jittered_grid(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const double h = 0.15 / (n - 1);
  Mesh m{Eigen::Matrix2Xd(2, n * n), {}};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool edge = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      m.xy.col(j * n + i) =
          h * Vec2(i + (edge ? 0.0 : jitter(rng)), j + (edge ? 0.0 : jitter(rng)));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if ((i + j) % 2 == 0)
        m.triangles.push_back({a, b, d}), m.triangles.push_back({a, d, c});
      else
        m.triangles.push_back({a, b, c}), m.triangles.push_back({b, d, c});
    }
  return m;
}

TEST(TriangleLocator, FindsTheFirstTriangleThatHoldsAPointAsAScanDoes) {
  const Mesh m = jittered_grid(40, 3);
  const TriangleLocator locator(m.xy, m.triangles);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.01, 0.16);
  std::vector<Vec2> points;
  for (int k = 0; k < 4000; ++k) points.emplace_back(u(rng), u(rng));
  // Vertices and edge midpoints: points that several triangles hold.
  for (Eigen::Index v = 0; v < m.xy.cols(); v += 7) points.emplace_back(m.xy.col(v));
  for (size_t t = 0; t < m.triangles.size(); t += 5)
    points.emplace_back(0.5 * (m.xy.col(m.triangles[t][0]) + m.xy.col(m.triangles[t][1])));
  // Just outside the rim, within the callers' tolerance of a triangle or beyond it.
  for (const double off : {1e-12, 1e-11, 1e-6})
    for (int k = 1; k < 10; ++k) {
      points.emplace_back(0.15 + off, 0.015 * k);
      points.emplace_back(0.015 * k, -off);
    }
  int inside = 0;
  for (const Vec2& p : points) {
    const auto holds = [&](int k) {
      const Triangle& t = m.triangles[static_cast<size_t>(k)];
      const auto w = weights(m.xy.col(t[0]), m.xy.col(t[1]), m.xy.col(t[2]), p);
      return w && w->minCoeff() >= -1e-9;
    };
    std::optional<int> scanned, located;
    for (int k = 0; k < static_cast<int>(m.triangles.size()) && !scanned; ++k)
      if (holds(k)) scanned = k;
    const auto c = locator.candidates(p);
    EXPECT_TRUE(std::is_sorted(c.begin(), c.end()));
    for (int k : c)
      if (!located && holds(k)) located = k;
    ASSERT_EQ(scanned, located) << p.transpose();
    inside += scanned.has_value();
  }
  EXPECT_GT(inside, 3000);  // most points lie on the mesh; some lie outside it
  // The points just off the rim by 1e-12 are held (within the tolerance) by a rim triangle.
  EXPECT_FALSE(locator.candidates(Vec2(0.15 + 1e-12, 0.0225)).empty());
  EXPECT_LT(inside, static_cast<int>(points.size()));
  // A handful of candidates per look-up, not the mesh.
  EXPECT_LT(locator.candidates(Vec2(0.07, 0.07)).size(), 20u);
}

// A fan of long slivers (a large polygon split from one corner) would fill the buckets many
// times over: every triangle is a candidate instead, so look-ups stay right.
TEST(TriangleLocator, ScansAFanOfSlivers) {
  const int k = 2000;
  Eigen::Matrix2Xd xy(2, k + 1);
  xy.col(0) = Vec2(0.0, 0.0);
  for (int i = 0; i < k; ++i) {
    const double a = 0.5 * std::acos(-1.0) * i / (k - 1);
    xy.col(i + 1) = Vec2(std::cos(a), std::sin(a));
  }
  std::vector<Triangle> fan;
  for (int i = 1; i < k; ++i) fan.push_back({0, i, i + 1});
  const TriangleLocator locator(xy, fan);
  EXPECT_EQ(locator.candidates(Vec2(0.3, 0.3)).size(), fan.size());
  EXPECT_TRUE(locator.candidates(Vec2(-0.5, 0.3)).empty());
}

TEST(TriangleLocator, HasNoCandidatesOutsideTheMeshOrForAnEmptyOne) {
  const Mesh m = jittered_grid(5, 1);
  const TriangleLocator locator(m.xy, m.triangles);
  EXPECT_TRUE(locator.candidates(Vec2(-0.05, 0.07)).empty());
  EXPECT_TRUE(locator.candidates(Vec2(0.07, 0.2)).empty());
  EXPECT_TRUE(locator.candidates(Vec2(std::nan(""), 0.07)).empty());
  EXPECT_FALSE(locator.candidates(Vec2(0.15, 0.15)).empty());  // the far corner is on the mesh
  const TriangleLocator empty(Eigen::Matrix2Xd(2, 0), {});
  EXPECT_TRUE(empty.candidates(Vec2(0.0, 0.0)).empty());
}

}  // namespace
}  // namespace membra
