// The spring kernel and the force pass: forces are exactly minus the energy gradient.
#include <random>

#include <gtest/gtest.h>

#include "membra/model/elements/spring_kernel.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/sheet.hpp"

namespace membra {
namespace {

TEST(SpringKernel, ForceIsStiffnessTimesExtensionAlongTheSpring) {
  const Vec3 xa(0.1, -0.2, 0.3), xb(0.4, 0.2, 0.3);  // length 0.5
  const double k = 250.0, l0 = 0.4;
  const Vec3 f = spring_force_on_a(xa, xb, Vec3::Zero(), Vec3::Zero(), l0, k, 0.0);
  const Vec3 expected = k * (0.5 - l0) * (xb - xa) / 0.5;
  EXPECT_NEAR((f - expected).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.norm(), 25.0, 1e-12);  // 250 N/m x 0.1 m, pulling a towards b
  EXPECT_GT(f.dot(xb - xa), 0.0);
  EXPECT_NEAR(spring_energy(xa, xb, l0, k), 0.5 * 250.0 * 0.01, 1e-12);
}

TEST(SpringKernel, CompressedSpringPushesApart) {
  const Vec3 f =
      spring_force_on_a(Vec3::Zero(), Vec3(0.3, 0, 0), Vec3::Zero(), Vec3::Zero(), 0.5, 10.0, 0.0);
  EXPECT_NEAR(f.x(), -2.0, 1e-12);
}

TEST(SpringKernel, DampingActsOnlyOnRelativeVelocityAlongTheSpring) {
  const Vec3 xa = Vec3::Zero(), xb(1, 0, 0);
  // Sideways relative motion: no damping force.
  Vec3 f = spring_force_on_a(xa, xb, Vec3::Zero(), Vec3(0, 3, 0), 1.0, 5.0, 2.0);
  EXPECT_NEAR(f.norm(), 0.0, 1e-12);
  // b moving away at 3 m/s with c = 2 N s/m: a is pulled along +x with 6 N.
  f = spring_force_on_a(xa, xb, Vec3::Zero(), Vec3(3, 1, 0), 1.0, 5.0, 2.0);
  EXPECT_NEAR(f.x(), 6.0, 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
}

TEST(SpringKernel, ZeroLengthSpringExertsNoForce) {
  const Vec3 f =
      spring_force_on_a(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3::Zero(), Vec3::Zero(), 0.2, 10.0, 0.0);
  EXPECT_EQ(f.norm(), 0.0);
}

// Central differences of the potential energy match the static force to 1e-6 (relative), for a
// randomly deformed sheet with all spring families and gravity, at sheet scale (mm) and at x1e-6.
class ForceGradient : public ::testing::TestWithParam<double> {};

TEST_P(ForceGradient, FiniteDifferencesOfEnergyMatchForces) {
  const double scale = GetParam();
  SheetOptions o;
  o.flex = true;
  const Sheet sheet = build_sheet({0.02 * scale, 0.02 * scale, 5, 5}, o);
  Model m = sheet.model;
  m.gravity = Vec3(0, 0, -9.81);
  for (auto& l0 : m.springs.rest_length) l0 *= 0.8;  // pre-stressed
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Points x = m.reference;
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] += u(rng) * 0.005 * scale;

  Points f;
  compute_static_forces(m, x, f);
  const double h = 1e-6 * 0.005 * scale;
  double max_err = 0.0, max_f = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Points xp = x, xm = x;
    xp.data()[i] += h;
    xm.data()[i] -= h;
    const double fd = -(potential_energy(m, xp) - potential_energy(m, xm)) / (2 * h);
    max_err = std::max(max_err, std::abs(fd - f.data()[i]));
    max_f = std::max(max_f, std::abs(f.data()[i]));
  }
  ASSERT_GT(max_f, 0.0);
  EXPECT_LT(max_err / max_f, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Scales, ForceGradient, ::testing::Values(1.0, 1e-3, 1e3));

TEST(Forces, GlobalDampingIsMinusDTimesMomentum) {
  Model m;
  m.add_particle(0.5, Vec3::Zero());
  m.velocity_damping = 3.0;
  Points x = Points::Zero(3, 1), v(3, 1), f;
  v.col(0) = Vec3(1, -2, 0.5);
  compute_forces(m, x, v, f);
  EXPECT_NEAR((f.col(0) - (-3.0 * 0.5 * v.col(0))).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace membra
