// Kirsch's round hole on the continuum sheet (issue: the edge concentration 3.0 within 3 % under
// uniaxial tension, 2.0 under equibiaxial; the lattice's staircase needs 15 %, kirsch_test.cpp).
// The hole's outline is an edge path of the mesh, as the scene's cut puts it there, and the
// mesh is graded from it: about a tenth of the radius at the edge, 10 mm far away. The edge
// value is extrapolated from the triangles' stresses (mesh_hole_edge.hpp). Under uniaxial tension
// the far stress s is the mean sigma_xx over a full cross-section away from the hole, which
// equilibrium makes the gross stress exactly (the free sides carry nothing). For a finite plate the
// gross concentration exceeds Kirsch's: 3.015 for this 240 mm plate and 16 mm hole (Heywood's fit),
// well inside the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "membra/measure/mesh_hole_edge.hpp"
#include "membra/model/continuum_hole.hpp"
#include "membra/model/continuum_sheet.hpp"
#include "membra/model/pattern_boundary.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace continuum_kirsch_test {
namespace {

constexpr double kSide = 0.24, kR = 0.008;
const Vec2 kCentre(0.5 * kSide, 0.5 * kSide);

struct Plate {
  Membrane m;
  std::vector<Vec2> removed;
  double s = 0.0;  // gross far stress sigma_xx, Pa
};

// The plate with the hole cut into its mesh, the hole punched, stretched by (ex, ey) between the
// held edges and solved in plane (linear law: small strain).
Plate stretched_plate(double ex, double ey, FrameEdges edges) {
  ContinuumSpec spec;
  spec.width = spec.height = kSide;
  spec.mesh.max_edge = 0.01;
  spec.mesh.elements_across = 20;  // across the hole's diameter: 0.8 mm at its edge
  spec.material.law = MembraneLaw::linear;
  const PatternPtr hole = make_ellipse(kCentre, kR, kR, 0.0);
  BoundaryOptions o;
  o.tolerance = spec.mesh.tolerance;
  spec.features = pattern_boundaries(*hole, Box2{Vec2::Zero(), Vec2(kSide, kSide)}, o);
  Plate p{make_membrane(build_continuum_sheet(spec)), {}, 0.0};
  EXPECT_GT(punch_continuum_hole(p.m, *hole, &p.removed), 20);
  stretch_frame(p.m, 1.0 + ex, 1.0 + ey, edges);
  NewtonOptions n;
  n.force_scale = p.m.sheet.stiffness.stretch * p.m.sheet.mesh.mean_edge;
  n.tolerance = 1e-10;
  n.in_plane = true;
  const SolveReport r = solve_newton(p.m.sheet.model, p.m.state, n);
  EXPECT_TRUE(r.converged) << r.message;
  // The gross stress: sigma_xx averaged over the cross-section 60-80 mm right of the hole.
  const MembraneTriangles& t = p.m.sheet.model.membrane_triangles;
  const Points& ref = p.m.sheet.model.reference;
  double force = 0.0, area = 0.0;
  for (int i = 0; i < t.size(); ++i) {
    const auto& v = t.v[static_cast<size_t>(i)];
    const Vec3 c = (ref.col(v[0]) + ref.col(v[1]) + ref.col(v[2])) / 3.0;
    if (c.x() < kCentre.x() + 0.06 || c.x() > kCentre.x() + 0.08) continue;
    const double a =
        0.5 * (ref.col(v[1]) - ref.col(v[0])).cross(ref.col(v[2]) - ref.col(v[0])).norm();
    force += a * t.stress_tensor(i, p.m.state.x)(0, 0);
    area += a;
  }
  p.s = force / area;
  return p;
}

double hoop(const Plate& p, const MeshHole& hole, double degrees) {
  const auto v = mesh_edge_hoop(p.m.sheet, p.m.state.x, hole, degrees * std::numbers::pi / 180.0);
  EXPECT_TRUE(v.has_value()) << degrees << " deg";
  return v.value_or(0.0) / p.s;
}

TEST(ContinuumKirsch, UniaxialTensionConcentratesThreefoldAtTheEdge) {
  const double e = 1e-3;  // the free sides contract by nu e (linear law: nu 1/3)
  const Plate p = stretched_plate(e, -e / 3.0, FrameEdges{true, true, false, false});
  ASSERT_GT(p.s, 0.0);
  const auto hole = find_mesh_hole(p.m.sheet, p.removed);
  ASSERT_TRUE(hole.has_value());
  EXPECT_NEAR(hole->radius, kR, 1e-3 * kR);
  const double top = hoop(p, *hole, 90.0), bottom = hoop(p, *hole, 270.0);
  const double left = hoop(p, *hole, 180.0), right = hoop(p, *hole, 0.0);
  std::printf("continuum Kirsch, uniaxial: top %.4f bottom %.4f (3), sides %.4f %.4f (-1)\n", top,
              bottom, left, right);
  EXPECT_NEAR(top, 3.0, 0.03 * 3.0);
  EXPECT_NEAR(bottom, 3.0, 0.03 * 3.0);
  EXPECT_NEAR(left, -1.0, 0.05);
  EXPECT_NEAR(right, -1.0, 0.05);
  // Between them Kirsch's 1 - 2 cos 2 theta.
  for (double deg : {30.0, 45.0, 60.0, 120.0, 135.0}) {
    const double want = 1.0 - 2.0 * std::cos(2.0 * deg * std::numbers::pi / 180.0);
    EXPECT_NEAR(hoop(p, *hole, deg), want, 0.05 * 3.0) << deg << " deg";
  }
  // The report's reading: the largest edge value over the rays, above or below the hole.
  const HoleEdge he = mesh_hole_edge(p.m.sheet, p.m.state.x, p.removed);
  ASSERT_TRUE(he.valid);
  EXPECT_NEAR(he.value / p.s, 3.0, 0.03 * 3.0);
  EXPECT_NEAR(std::abs(std::sin(he.angle)), 1.0, 0.01);
}

TEST(ContinuumKirsch, EquibiaxialTensionConcentratesTwofoldAllRound) {
  const double e = 1e-3;
  Plate p = stretched_plate(e, e, FrameEdges{});
  // Held all round, the frame's edges carry shear too and no section's force is the far field's:
  // s is the plate's without the hole, E e / (1 - nu) (the hole changes it by (R / side)^2).
  p.s = p.m.sheet.material.youngs_modulus * e / (1.0 - 1.0 / 3.0);
  const auto hole = find_mesh_hole(p.m.sheet, p.removed);
  ASSERT_TRUE(hole.has_value());
  for (double deg = 0.0; deg < 360.0; deg += 30.0) {
    const double v = hoop(p, *hole, deg);
    std::printf("continuum Kirsch, equibiaxial, %3.0f deg: %.4f (2)\n", deg, v);
    EXPECT_NEAR(v, 2.0, 0.03 * 2.0) << deg << " deg";
  }
}

}  // namespace
}  // namespace continuum_kirsch_test
}  // namespace membra
