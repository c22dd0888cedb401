#include "membra/geometry/conforming_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

namespace membra {
namespace {

double area(const PlanarMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    const Vec2 u = m.vertices[t[1]] - m.vertices[t[0]], v = m.vertices[t[2]] - m.vertices[t[0]];
    a += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return a;
}

// True when the segment a-b is covered by mesh edges (its points lie on edges between vertices
// on it): the mesh follows the constraint.
bool follows(const PlanarMesh& m, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  auto on = [&](const Vec2& p) {
    const double t = (p - a).dot(e) / e.squaredNorm();
    return t >= -1e-12 && t <= 1 + 1e-12 &&
           std::abs(e.x() * (p - a).y() - e.y() * (p - a).x()) < 1e-12 * e.norm();
  };
  double covered = 0.0;
  std::set<std::pair<int, int>> seen;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int p = t[k], q = t[(k + 1) % 3];
      if (!seen.insert(std::minmax(p, q)).second) continue;
      if (on(m.vertices[p]) && on(m.vertices[q])) covered += (m.vertices[q] - m.vertices[p]).norm();
    }
  return std::abs(covered - e.norm()) < 1e-9;
}

MeshRequest square_with_piece(double h) {
  MeshRequest r;
  r.outline = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // A small square piece inside, and a strip that reaches the outline on both sides.
  r.constraints = {{{0.3, 0.3}, {0.4, 0.3}, {0.4, 0.4}, {0.3, 0.4}},
                   {{0.0, 0.7}, {1.0, 0.7}, {1.0, 0.75}, {0.0, 0.75}}};
  r.size = [h](const Vec2&) { return h; };
  return r;
}

TEST(ConformingMesh, CoversTheRegionAndFollowsEveryConstraint) {
  const PlanarMesh m = conforming_mesh(square_with_piece(0.05));
  EXPECT_NEAR(area(m), 1.0, 1e-12);  // counter-clockwise triangles tile the square exactly
  for (const auto& poly : square_with_piece(0.05).constraints)
    for (size_t i = 0; i < poly.size(); ++i)
      EXPECT_TRUE(follows(m, poly[i], poly[(i + 1) % poly.size()])) << i;
  EXPECT_TRUE(follows(m, {0, 0}, {1, 0}));
}

TEST(ConformingMesh, MeetsItsSizeAndAngle) {
  const MeshRequest r = square_with_piece(0.05);
  const PlanarMesh m = conforming_mesh(r);
  EXPECT_GE(m.min_angle_deg(), r.min_angle_deg - 1e-9);
  EXPECT_LE(m.max_edge(), 0.05 * (1 + 1e-9));
  // A strip edge meeting the outline leaves no sliver: nothing much shorter than the strip.
  EXPECT_GT(m.min_edge(), 0.01);
}

TEST(ConformingMesh, FollowsAGradedSize) {
  MeshRequest r = square_with_piece(0.0);
  r.size = [](const Vec2& p) { return 0.01 + 0.1 * p.x(); };
  const PlanarMesh m = conforming_mesh(r);
  // Smaller triangles on the left than on the right.
  double left = 0.0, right = 0.0;
  int nl = 0, nr = 0;
  for (const auto& t : m.triangles) {
    const Vec2 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    const double e = (m.vertices[t[1]] - m.vertices[t[0]]).norm();
    if (c.x() < 0.2) left += e, ++nl;
    if (c.x() > 0.8) right += e, ++nr;
  }
  EXPECT_LT(left / nl * 3.0, right / nr);
}

TEST(ConformingMesh, MeshesADiskInsideItsPolygon) {
  MeshRequest r;
  for (int k = 0; k < 64; ++k) {
    const double t = 2 * std::numbers::pi * k / 64;
    r.outline.emplace_back(std::cos(t), std::sin(t));
  }
  r.size = [](const Vec2&) { return 0.2; };
  const PlanarMesh m = conforming_mesh(r);
  EXPECT_NEAR(area(m), 32 * std::sin(2 * std::numbers::pi / 64), 1e-12);
}

// A fine mesh of a finely sampled circle (100 mm across, chords of about 2.8 mm split by the
// mesher's 2.5 mm): no sliver between a chord and its two halves, every triangle at least the
// requested angle, the area the polygon's. Such slivers (three split points in a line, zero
// area) once made `membra run` refuse disk sheets at max_edge 3 mm and below.
TEST(ConformingMesh, SplittingACurvedOutlinesChordsLeavesNoSliver) {
  MeshRequest r;
  const int n = 112;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    r.outline.emplace_back(0.05 + 0.05 * std::cos(t), 0.05 + 0.05 * std::sin(t));
  }
  r.size = [](const Vec2&) { return 0.0025; };
  const PlanarMesh m = conforming_mesh(r);
  EXPECT_GT(m.min_angle_deg(), r.min_angle_deg - 1e-9);
  EXPECT_NEAR(area(m), 0.5 * n * 0.0025 * std::sin(2 * std::numbers::pi / n), 1e-12);
}

TEST(ConformingMesh, RefusesTooManyVerticesAndADegenerateOutline) {
  MeshRequest r = square_with_piece(0.001);
  r.max_vertices = 1000;
  EXPECT_THROW(conforming_mesh(r), std::runtime_error);
  r.outline.resize(2);
  EXPECT_THROW(conforming_mesh(r), std::invalid_argument);
}

}  // namespace
}  // namespace membra
