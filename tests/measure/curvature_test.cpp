// Angle-defect Gaussian curvature and cotangent mean curvature against analytic surfaces.
#include <cmath>
#include <map>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {
namespace {

constexpr double kPi = std::numbers::pi;

// Icosahedron subdivided `levels` times, projected onto a sphere of radius r.
void icosphere(int levels, double r, Points& x, std::vector<Triangle>& tris) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  tris = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
          {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      v.push_back(0.5 * (v[a] + v[b]));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Triangle> next;
    for (const Triangle& f : tris) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.insert(next.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    tris = next;
  }
  x.resize(3, static_cast<Eigen::Index>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = r * v[i].normalized();
}

class Sphere : public ::testing::TestWithParam<double> {};

TEST_P(Sphere, GaussBonnetAndDensityOneOverRSquared) {
  const double r = GetParam();
  Points x;
  std::vector<Triangle> tris;
  icosphere(5, r, x, tris);
  const GaussianCurvature k = gaussian_curvature(x, tris);
  EXPECT_NEAR(k.total, 4.0 * kPi, 1e-9);  // closed surface of genus 0
  EXPECT_EQ(k.boundary, 0.0);
  for (size_t v = 0; v < k.density.size(); ++v) ASSERT_NEAR(k.density[v] * r * r, 1.0, 0.02) << v;
  EXPECT_EQ(classify_form(k), "synclastic");
}

INSTANTIATE_TEST_SUITE_P(Scales, Sphere, ::testing::Values(1.0, 1e-3, 1e3));

// A grid sheet of n x n nodes over [-1, 1]^2 lifted by z = f(x, y).
template <class F>
void lifted_grid(int n, F f, Points& x, std::vector<Triangle>& tris, GridSheet& g) {
  g = GridSheet({2.0, 2.0, n, n});
  tris = triangulate(g);
  x.resize(3, g.num_particles());
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j) - Vec2(1.0, 1.0);
    x.col(p) = Vec3(q.x(), q.y(), f(q.x(), q.y()));
  }
}

TEST(Curvature, DiskGaussBonnetIsTwoPi) {
  Points x;
  std::vector<Triangle> tris;
  GridSheet g;
  lifted_grid(
      21, [](double u, double v) { return 0.3 * std::sin(u) * std::cos(2 * v); }, x, tris, g);
  const GaussianCurvature k = gaussian_curvature(x, tris);
  EXPECT_NEAR(k.total + k.boundary, 2.0 * kPi, 1e-9);
}

TEST(Curvature, PlaneIsFlat) {
  Points x;
  std::vector<Triangle> tris;
  GridSheet g;
  lifted_grid(
      11, [](double u, double v) { return 0.2 * u - 0.7 * v; }, x, tris, g);
  const GaussianCurvature k = gaussian_curvature(x, tris);
  for (size_t v = 0; v < k.density.size(); ++v)
    EXPECT_NEAR(k.angle_defect[v] * (k.interior[v] ? 1 : 0), 0.0, 1e-12);
  EXPECT_EQ(classify_form(k), "developable");
}

TEST(Curvature, SaddleHasMinusOneAtItsCentre) {
  Points x;
  std::vector<Triangle> tris;
  GridSheet g;
  lifted_grid(
      201, [](double u, double v) { return u * v; }, x, tris, g);
  GaussianCurvature k = gaussian_curvature(x, tris);
  // Raw defects alternate with the vertex valence; the grid filter gives K = -1.
  EXPECT_NEAR(k.density[g.particle(100, 100)] + k.density[g.particle(101, 100)], -2.0, 0.05);
  smooth_density_on_grid(g, k);
  for (int i : {100, 101}) EXPECT_NEAR(k.density[g.particle(i, 100)], -1.0, 0.05) << i;
  EXPECT_EQ(classify_form(k), "anticlastic");
}

TEST(Curvature, CylinderHasNoGaussianAndHalfOverRMeanCurvature) {
  const double r = 2.0;
  Points x;
  std::vector<Triangle> tris;
  GridSheet g;
  // The sheet wrapped isometrically around a cylinder of radius r with axis along y.
  lifted_grid(
      81, [](double, double) { return 0.0; }, x, tris, g);
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double u = x(0, p);
    x(0, p) = r * std::sin(u / r);
    x(2, p) = r * (1.0 - std::cos(u / r));
  }
  const GaussianCurvature k = gaussian_curvature(x, tris);
  const std::vector<double> h = mean_curvature(x, tris);
  for (int p = 0; p < g.num_particles(); ++p) {
    if (!k.interior[p]) continue;
    EXPECT_NEAR(k.density[p], 0.0, 1e-9);
    EXPECT_NEAR(h[p] * 2.0 * r, 1.0, 0.03) << p;
  }
  EXPECT_EQ(classify_form(k), "developable");
}

}  // namespace
}  // namespace membra
