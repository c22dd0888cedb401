// The continuum sheet's Gaussian-curvature term (model/elements/angle_defects.hpp): with the
// shell hinges it gives Kirchhoff's plate on spheres and saddles; finite differences; nothing on
// a flat sheet.
#include "membra/model/elements/angle_defects.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "element_checks.hpp"
#include "membra/model/elements/shell_hinges.hpp"

namespace membra {
namespace {

constexpr double kPlateD = 1.5e6 * 1.25e-10 / 9.0;  // N m: latex, nu 1/2

// Kirchhoff's plate stores (D/2)(k1^2 + k2^2 + 2 nu k1 k2): with nu = 1/2, 3 (D/2) k^2 on a
// sphere and 1 on a saddle per unit area. The hinges alone store 4/3 and 8/3; with the angle
// defects the sum is the plate's, within 5 % (the rim's cells are counted by neither quite
// alike).
TEST(AngleDefects, WithTheHingesASphereAndASaddleStoreThePlateEnergy) {
  const TriPatch m = tri_patch(30, 0.002, 0.2);
  ShellHinges h;
  h.add_mesh(m.triangles, m.x, kPlateD);
  AngleDefects a;
  EXPECT_DOUBLE_EQ(angle_defect_coefficient(0.5), 5.0 / 3.0);
  a.add_mesh(m.triangles, m.x, angle_defect_coefficient(0.5) * kPlateD, m.rim);
  double owned = 0.0;
  for (const auto& s : h.side_area) owned += (s[0] + s[1]) / 3.0;
  const double r = 0.5;
  const Vec3 centre = m.x.rowwise().mean();
  Points sphere = m.x, saddle = m.x;
  for (int p = 0; p < m.x.cols(); ++p) {
    const Vec3 d = m.x.col(p) - centre;
    const double rho = d.norm(), phi = rho / r, s = rho > 0.0 ? std::sin(phi) / rho : 1.0 / r;
    sphere.col(p) = centre + Vec3(r * s * d.x(), r * s * d.y(), r * (1.0 - std::cos(phi)));
    saddle(2, p) = (d.x() * d.x() - d.y() * d.y()) / (2.0 * r);
  }
  const double unit = 0.5 * kPlateD / (r * r) * owned;
  const double on_sphere = (set_energy(h, sphere) + set_energy(a, sphere)) / unit,
               on_saddle = (set_energy(h, saddle) + set_energy(a, saddle)) / unit;
  EXPECT_NEAR(on_sphere, 3.0, 0.15);
  EXPECT_NEAR(on_saddle, 1.0, 0.05);
  std::printf("plate energy / (D/2)k^2: sphere %.4f (3), saddle %.4f (1)\n", on_sphere, on_saddle);
  // A flat sheet, however it is sheared in its plane, has no angle defect.
  Points sheared = m.x;
  sheared.row(0) += 0.3 * m.x.row(1);
  EXPECT_NEAR(set_energy(a, sheared), 0.0, 1e-9 * unit);  // round-off of 3 600 angle sums
}

TEST(AngleDefects, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points rest = Points::Zero(3, 3);
  rest.col(1) = Vec3(0.01, 0.001, 0.0);
  rest.col(2) = Vec3(0.003, 0.009, 0.0);
  for (int trial = 0; trial < 4; ++trial) {
    AngleDefects a;
    // Corners 0 and 2 interior, 1 on the rim, the two of different weights.
    a.add_mesh({{0, 1, 2}}, rest, 5.0 / 3.0 * kPlateD, {1});
    a.weight[0][2] *= 3.0;
    Points x = rest;
    for (int k = 0; k < 9; ++k) x(k % 3, k / 3) += 0.003 * u(rng);
    expect_kernel_matches_finite_differences(a, x, "angle defects");
  }
}

}  // namespace
}  // namespace membra
