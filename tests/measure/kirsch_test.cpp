// Stress around a round hole against Kirsch's solution (infinite plate, small strain). With far
// stress s along x, the hoop stress at radius r >= R above the hole (theta = 90 deg) is
//   s/2 (2 + R^2/r^2 + 3 R^4/r^4)  (3s at the edge),
// beside it on the load axis s/2 (R^2/r^2 - 3 R^4/r^4) (-s at the edge), and under equibiaxial
// tension s (1 + R^2/r^2) all round (2s at the edge). In plane stress the stresses of a traction
// problem do not depend on Poisson's ratio (Michell), so the lattice's fixed nu = 1/3 does not
// enter; it sets the hole's change of shape only.
//
// membra's hole is a staircase of grid cells. Its stress field matches Kirsch's for the circle of
// the same area from two spacings off the edge; on the edge the staircase's flat runs carry less
// (measured 0.78x) and its corners more - the known staircase effect of grid models, which does
// not shrink as the grid is refined. These tests pin both facts down, and check the edge value
// extrapolated from 3-8 spacings off the edge (hole_edge.hpp) against Kirsch's: the 15 %
// (docs/deformation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "membra/measure/hole_edge.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/cut.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace {

constexpr double kH = 1e-3;      // grid spacing, m
constexpr int kN = 181;          // a 180 mm plate: more than 10 hole diameters
constexpr int kC = 90;           // hole centre node (x = y)
constexpr double kR = 8.5 * kH;  // nodes closer than 8.5 spacings go

struct Plate {
  Membrane m;
  NodeStress stress;
  double radius = 0.0;  // of the circle with the hole's area, m
};

// The plate with its hole, stretched by (ex, ey) between the held frame edges, solved in plane.
Plate stretched_plate(double ex, double ey, FrameEdges edges) {
  SheetOptions o;
  o.bending = false;  // a flat in-plane problem
  Plate p{make_membrane(build_sheet({(kN - 1) * kH, (kN - 1) * kH, kN, kN}, o)), {}, 0.0};
  auto mass = [&] {
    const auto& m = p.m.sheet.model.mass;
    return std::accumulate(m.begin(), m.end(), 0.0);
  };
  const double mass0 = mass();
  EXPECT_GT(punch_hole(p.m, *make_ellipse(Vec2(kC * kH, kC * kH), kR, kR, 0.0)), 200);
  const double cell_mass = kH * kH * p.m.sheet.material.thickness * p.m.sheet.material.density;
  p.radius = kH * std::sqrt((mass0 - mass()) / cell_mass / std::numbers::pi);
  stretch_frame(p.m, 1.0 + ex, 1.0 + ey, edges);
  NewtonOptions n;
  n.force_scale = p.m.sheet.stiffness.stretch * kH;
  n.tolerance = 1e-9;
  n.in_plane = true;  // without bending the compressed side of the hole would wrinkle
  const SolveReport r = solve_newton(p.m.sheet.model, p.m.state, n);
  EXPECT_TRUE(r.converged) << r.message;
  p.stress =
      node_stress(p.m.sheet.grid, p.m.sheet.model, p.m.state.x, p.m.sheet.material.thickness);
  return p;
}

double at(const Plate& p, int i, int j, int component) {
  const int q = p.m.sheet.grid.particle(i, j);
  EXPECT_GE(q, 0) << i << ", " << j;
  return q >= 0 ? p.stress.sigma[q](component, component) : 0.0;
}

// The normal stress n^T sigma n across the in-plane unit vector n, at every particle.
std::vector<double> normal_stress(const Plate& p, const Vec2& n) {
  const Vec3 n3(n.x(), n.y(), 0.0);
  std::vector<double> v;
  for (const auto& s : p.stress.sigma) v.push_back(n3.dot(s * n3));
  return v;
}

// The hoop stress (across the ray) extrapolated to the equal-area circle along `direction`
// (hole_edge.hpp).
double edge_hoop(const Plate& p, const Vec2& direction) {
  const auto v = edge_value(p.m.sheet.grid, normal_stress(p, Vec2(-direction.y(), direction.x())),
                            Vec2(kC * kH, kC * kH), p.radius, direction);
  EXPECT_TRUE(v.has_value());
  return v.value_or(0.0);
}

// First node row above the hole on the centre column.
int edge_row(const Plate& p) {
  int j = kC;
  while (p.m.sheet.grid.particle(kC, j) < 0) ++j;
  return j;
}

TEST(Kirsch, UniaxialTensionMatchesKirschOffTheEdge) {
  // Strains of a free uniaxial state (lateral contraction nu = 1/3), so that the grips on the left
  // and right apply uniform tension.
  const double e = 1e-3;
  const Plate p = stretched_plate(e, -e / 3.0, FrameEdges{true, true, false, false});
  const double s = at(p, kC, 10, 0);  // far field, between the grips
  ASSERT_GT(s, 0.0);
  EXPECT_LT(std::abs(at(p, kC, 10, 1)), 0.02 * s);  // uniaxial there
  EXPECT_NEAR(p.radius / kH, 9.0, 0.5);
  const int edge = edge_row(p);
  const double R2 = p.radius * p.radius;
  for (int d = 2; d <= 20; ++d) {
    const double r = (edge - kC + d) * kH, q = R2 / (r * r);
    // Above: hoop = sigma_xx. Beside (on the load axis): hoop = sigma_yy.
    EXPECT_NEAR(at(p, kC, edge + d, 0) / s, 0.5 * (2 + q + 3 * q * q), 0.06) << "above, r = " << r;
    EXPECT_NEAR(at(p, edge + d, kC, 1) / s, 0.5 * (q - 3 * q * q), 0.06) << "beside, r = " << r;
  }
  // On the edge itself: the top carries the peak, well above the far field; the side is in
  // compression of about the far-field stress.
  const double top = at(p, kC, edge, 0) / s, side = at(p, edge, kC, 1) / s;
  std::printf("uniaxial edge: top %.3f (Kirsch 3), side %.3f (Kirsch -1), equal-area R %.2f h\n",
              top, side, p.radius / kH);
  EXPECT_GT(top, 2.0);
  EXPECT_NEAR(side, -1.0, 0.25);
  // Extrapolated from 2-6 spacings off the edge: the 15 % on the peak, and about -1 on
  // the load axis.
  const double top_x = edge_hoop(p, Vec2(0, 1)) / s, bottom_x = edge_hoop(p, Vec2(0, -1)) / s;
  const double side_x = edge_hoop(p, Vec2(1, 0)) / s;
  std::printf("uniaxial edge, extrapolated: top %.3f, bottom %.3f, side %.3f\n", top_x, bottom_x,
              side_x);
  EXPECT_NEAR(top_x, 3.0, 0.15 * 3.0);
  EXPECT_NEAR(bottom_x, 3.0, 0.15 * 3.0);
  EXPECT_NEAR(side_x, -1.0, 0.15);
  // The report's measure: the largest principal stress, largest over the rays, lies above or
  // below the hole.
  std::vector<Vec2> removed;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i)
      if (p.m.sheet.grid.particle(i, j) < 0) removed.emplace_back(i * kH, j * kH);
  const HoleEdge he = hole_edge(p.m.sheet.grid, max_principal_stress(p.stress), removed);
  ASSERT_TRUE(he.valid);
  EXPECT_NEAR(he.value / s, 3.0, 0.15 * 3.0);
  EXPECT_NEAR(std::abs(std::sin(he.angle)), 1.0, 0.05);
  EXPECT_NEAR(he.radius, p.radius, 1e-9);
}

TEST(Kirsch, EquibiaxialTensionMatchesKirschOffTheEdge) {
  const double e = 1e-3;
  const Plate p = stretched_plate(e, e, FrameEdges{});
  const double s = at(p, 20, 20, 0);
  ASSERT_GT(s, 0.0);
  EXPECT_NEAR(at(p, 20, 20, 1) / s, 1.0, 0.01);
  const int edge = edge_row(p);
  const double R2 = p.radius * p.radius;
  for (int d = 2; d <= 20; ++d) {
    const double r = (edge - kC + d) * kH;
    EXPECT_NEAR(at(p, kC, edge + d, 0) / s, 1.0 + R2 / (r * r), 0.05) << "r = " << r;
  }
  const double top = at(p, kC, edge, 0) / s;
  std::printf("equibiaxial edge: %.3f (Kirsch 2)\n", top);
  EXPECT_GT(top, 1.4);
  for (double t = 0.0; t < 6.28; t += 0.5) {
    const double hoop = edge_hoop(p, Vec2(std::cos(t), std::sin(t))) / s;
    std::printf("equibiaxial edge, extrapolated, angle %.1f: %.3f\n", t, hoop);
    EXPECT_NEAR(hoop, 2.0, 0.15 * 2.0) << "angle " << t;
  }
}

}  // namespace
}  // namespace membra
