// Bending elements: gradient, and the plate energy (D/2)(k1^2 + k2^2 + 2 nu k1 k2), nu = 1/3,
// for cylinders, spheres and saddles in every orientation on the grid.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "membra/model/elements/bend_kernel.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/sheet.hpp"

namespace membra {
namespace {

TEST(BendKernel, GradientMatchesFiniteDifferences) {
  const std::array<Vec3, 3> x = {Vec3(0, 0, 0), Vec3(1.0, 0.2, 0.1), Vec3(1.8, 0.9, -0.3)};
  const double c = 0.7;
  const BendEval e = bend_eval(x[0], x[1], x[2], c);
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d) {
      auto xp = x, xm = x;
      const double h = 1e-6;
      xp[i][d] += h;
      xm[i][d] -= h;
      const double fd =
          (bend_eval(xp[0], xp[1], xp[2], c).energy - bend_eval(xm[0], xm[1], xm[2], c).energy) /
          (2 * h);
      EXPECT_NEAR(fd, e.grad[i][d], 1e-7 * std::max(1.0, std::abs(fd))) << i << "," << d;
    }
}

TEST(BendKernel, EnergyIsFourCTanSquaredOfHalfTheTurningAngle) {
  for (double psi : {1e-4, 0.1, 0.5, 1.0, 2.0}) {
    const Vec3 x0(-1, 0, 0), x1(0, 0, 0), x2(2.0 * std::cos(psi), 2.0 * std::sin(psi), 0.0);
    const double t = std::tan(psi / 2);
    EXPECT_NEAR(bend_eval(x0, x1, x2, 3.0).energy, 12.0 * t * t, 1e-12 * (1 + t * t)) << psi;
  }
  // Straight: no energy and no force.
  const BendEval s = bend_eval(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(3, 3, 3), 1.0);
  EXPECT_EQ(s.energy, 0.0);
  EXPECT_LT(s.grad[1].norm(), 1e-15);
}

struct Quadric {
  double k1, k2, angle_deg;
};

class PlateEnergy : public ::testing::TestWithParam<Quadric> {};

// The grid is laid on z = (k1 u^2 + k2 v^2) / 2 (u, v rotated by `angle` from x, y) with small
// slopes, and the energy density of the elements centred at the middle nodes is compared with
// the plate's.
TEST_P(PlateEnergy, DensityMatchesIsotropicPlateWithPoissonOneThird) {
  const Quadric q = GetParam();
  const int n = 21;
  const double h = 1e-3;  // 1 mm
  SheetOptions o;
  const Sheet s = build_sheet({h * (n - 1), h * (n - 1), n, n}, o);
  const double a = q.angle_deg * std::numbers::pi / 180.0;
  Points x = s.model.reference;
  for (int p = 0; p < x.cols(); ++p) {
    const double px = x(0, p) - 0.01, py = x(1, p) - 0.01;
    const double u = std::cos(a) * px + std::sin(a) * py, v = -std::sin(a) * px + std::cos(a) * py;
    x(2, p) = 0.5 * (q.k1 * u * u + q.k2 * v * v);
  }
  const Bending& b = s.model.bending;
  double energy = 0.0;
  int nodes = 0;
  std::vector<bool> counted(static_cast<size_t>(x.cols()), false);
  for (int i = 0; i < b.size(); ++i) {
    const auto [ci, cj] = s.grid.node(b.v[i][1]);
    if (std::abs(ci - 10) > 3 || std::abs(cj - 10) > 3) continue;
    energy +=
        bend_eval(x.col(b.v[i][0]), x.col(b.v[i][1]), x.col(b.v[i][2]), b.stiffness[i]).energy;
    if (!counted[b.v[i][1]]) counted[b.v[i][1]] = true, ++nodes;
  }
  ASSERT_EQ(nodes, 49);
  const double d = bending_stiffness(o.material);
  const double expected = 0.5 * d * (q.k1 * q.k1 + q.k2 * q.k2 + 2.0 / 3.0 * q.k1 * q.k2);
  EXPECT_NEAR(energy / (nodes * h * h) / expected, 1.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Shapes, PlateEnergy,
                         ::testing::Values(Quadric{1, 0, 0}, Quadric{1, 0, 22.5}, Quadric{1, 0, 45},
                                           Quadric{1, 0, 90}, Quadric{1, 0, 30}, Quadric{1, 1, 0},
                                           Quadric{1, 1, 17}, Quadric{1, -1, 0}, Quadric{1, -1, 45},
                                           Quadric{2, 0.5, 60}));

}  // namespace
}  // namespace membra
