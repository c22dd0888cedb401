// The polygon's edge grid answers as the plain loop over every edge does.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "membra/model/polygon_index.hpp"

namespace membra {
namespace {

bool brute_contains(const std::vector<Vec2>& v, const Vec2& p) {
  bool in = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
      in = !in;
  return in;
}

double brute_distance(const std::vector<Vec2>& v, const Vec2& p) {
  double best = 1e300;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Vec2 ab = v[i] - v[j];
    const double t = std::clamp((p - v[j]).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (v[j] + t * ab - p).norm());
  }
  return best;
}

// A jagged star: self-touching spikes, long and short edges, axis-parallel runs.
std::vector<Vec2> star(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.2, 1.0);
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / n, r = k % 7 == 0 ? 1.0 : radius(rng);
    v.emplace_back(0.05 * r * std::cos(a) + 0.1, 0.03 * r * std::sin(a) + 0.07);
  }
  v.emplace_back(0.1, 0.07);  // a run back to the centre and out again
  return v;
}

TEST(PolygonIndex, EqualsTheLoopOverEveryEdge) {
  for (int n : {3, 10, 200, 2000}) {
    const std::vector<Vec2> v = star(n, static_cast<unsigned>(n));
    const PolygonIndex index(v);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(0.0, 0.2), y(0.0, 0.14);
    for (int k = 0; k < 500; ++k) {
      const Vec2 p(x(rng), y(rng));
      ASSERT_EQ(index.contains(p), brute_contains(v, p)) << n << ": " << p.transpose();
      ASSERT_NEAR(index.distance(p), brute_distance(v, p), 1e-15) << n << ": " << p.transpose();
    }
    // Points far outside the box: the search widens until it has seen enough.
    for (const Vec2& p : {Vec2(-1.0, -1.0), Vec2(5.0, 0.07), Vec2(0.1, -3.0)}) {
      EXPECT_FALSE(index.contains(p));
      EXPECT_NEAR(index.distance(p), brute_distance(v, p), 1e-12);
    }
  }
}

TEST(PolygonIndex, AHundredThousandVertexCircle) {
  const int n = 100000;
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k)
    v.emplace_back(0.04 * std::cos(2.0 * M_PI * k / n), 0.025 * std::sin(2.0 * M_PI * k / n));
  const PolygonIndex index(v);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-0.05, 0.05), y(-0.03, 0.03);
  for (int k = 0; k < 60; ++k) {
    const Vec2 p(x(rng), y(rng));
    EXPECT_EQ(index.contains(p), brute_contains(v, p));
    EXPECT_NEAR(index.distance(p), brute_distance(v, p), 1e-15);
    // The bounded search of the pattern's field: exact near the outline, never below the truth.
    const double bounded = index.distance(p, 3), exact = brute_distance(v, p);
    EXPECT_GE(bounded, exact - 1e-15);
    if (exact < 0.7e-3) {
      EXPECT_NEAR(bounded, exact, 1e-15);  // within 3 cells (0.76 mm here) it is exact
    }
  }
}

// Degenerate but accepted outlines: all points on a line, all the same point, and a star whose
// every edge crosses the whole shape (each edge occupies a line of cells, not its box).
TEST(PolygonIndex, DegenerateAndCrossingOutlines) {
  const std::vector<std::vector<Vec2>> shapes = {
      {{0.0, 0.0}, {0.01, 0.0}, {0.02, 0.0}, {0.03, 0.0}},
      {{0.05, 0.05}, {0.05, 0.05}, {0.05, 0.05}},
      {}};
  std::vector<std::vector<Vec2>> all = shapes;
  auto& star = all.back();
  const int n = 20001;  // a {n/2}-pointed star polygon: edges from one side to the other
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * ((k * (n / 2)) % n) / n;
    star.emplace_back(0.05 * std::cos(a), 0.05 * std::sin(a));
  }
  for (const auto& v : all) {
    const PolygonIndex index(v);
    for (const Vec2& p :
         {Vec2(0.0, 0.0), Vec2(0.015, 1e-9), Vec2(1e6, -1e6), Vec2(0.05, 0.05), Vec2(0.01, 0.02)}) {
      EXPECT_EQ(index.contains(p), brute_contains(v, p)) << v.size() << ": " << p.transpose();
      EXPECT_NEAR(index.distance(p), brute_distance(v, p), 1e-12 * (1.0 + p.norm()));
    }
  }
}

}  // namespace
}  // namespace membra
