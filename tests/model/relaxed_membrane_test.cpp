// Tension-field theory's relaxed membrane (model/membrane_law.hpp, "wrinkling": "relaxed"): the
// relaxed energy in its three states against closed forms, its smoothness where they meet, and
// the membrane triangles' gradient and Hessian on it against finite differences.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>
#include <string>

#include "element_checks.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/membrane_law.hpp"

namespace membra {
namespace relaxed_membrane_test {  // a unity build shares anonymous namespaces
namespace {

constexpr double kE = 1.5e6;  // Pa, latex
constexpr double kT = 5e-4;   // m

LawConstants relaxed(MembraneLaw law) {
  LawConstants k = law_constants(law, kE);
  k.relaxed = true;
  return k;
}

// The relaxed energy (no residual) at principal stretches (l1, l2).
double relaxed_w(const LawConstants& k, double l1, double l2) {
  return relaxed_strain_energy(k, l1 * l1 + l2 * l2, l1 * l1 * l2 * l2).w;
}
double full_w(const LawConstants& k, double l1, double l2) {
  return full_strain_energy(k, l1 * l1 + l2 * l2, l1 * l1 * l2 * l2).w;
}

// Slack stores nothing; wrinkled stores uniaxial tension's mu/2 (l^2 + 2/l - 3) whatever the
// lateral stretch below l^-1/2; taut stores the law itself (neo-Hookean, exact to round-off).
TEST(RelaxedMembrane, EachStateStoresItsClosedForm) {
  const LawConstants k = relaxed(MembraneLaw::neo_hookean);
  const double mu = k.c1;
  EXPECT_EQ(relaxed_w(k, 0.9, 0.7), 0.0);
  EXPECT_EQ(relaxed_w(k, 1.0, 0.5), 0.0);
  for (double l : {1.1, 1.5, 2.0}) {
    const double uniaxial = 0.5 * mu * (l * l + 2.0 / l - 3.0);
    for (double lateral : {0.3, 0.6, 0.95 / std::sqrt(l)})
      EXPECT_NEAR(relaxed_w(k, l, lateral) / uniaxial, 1.0, 1e-12) << l << " " << lateral;
    for (double lateral : {1.05 / std::sqrt(l), 1.0, l})
      EXPECT_NEAR(relaxed_w(k, l, lateral) / full_w(k, l, lateral), 1.0, 1e-12);
  }
}

// The relaxed energy is the least over finer wrinklings, so never more than the law's, and the
// law's own minimum over the lateral stretch where the sheet is wrinkled: both laws, a sweep.
TEST(RelaxedMembrane, NeverStoresMoreThanTheLawAndIsItsLateralMinimum) {
  for (MembraneLaw law : {MembraneLaw::neo_hookean, MembraneLaw::mooney_rivlin}) {
    const LawConstants k = relaxed(law);
    for (double l1 = 0.5; l1 < 2.5; l1 += 0.05)
      for (double l2 = 0.3; l2 <= l1; l2 += 0.05) {
        EXPECT_LE(relaxed_w(k, l1, l2), full_w(k, l1, l2) * (1.0 + 1e-12));
        if (l1 > 1.0 && l2 < 1.0 / std::sqrt(l1)) {
          const double lateral = uniaxial_lateral_stretch(law_constants(law, kE), l1);
          EXPECT_NEAR(relaxed_w(k, l1, l2), full_w(k, l1, lateral), 1e-9 * k.c1) << l1 << l2;
        }
      }
  }
}

// Where the states meet the energy and its first derivatives are continuous: across the
// slack-wrinkled boundary (l1 = 1) and the wrinkled-taut one (l2 = l1^-1/2), both laws.
TEST(RelaxedMembrane, TheStatesMeetWithTheirSlopes) {
  for (MembraneLaw law : {MembraneLaw::neo_hookean, MembraneLaw::mooney_rivlin}) {
    const LawConstants k = relaxed(law);
    const double h = 1e-7;
    auto at = [&](double i, double j) { return relaxed_strain_energy(k, i, j); };
    // Points on each boundary, in (I, J), stepped across it.
    const std::array<std::pair<double, double>, 2> boundary = {
        std::pair{1.0, 0.6}, std::pair{1.4, 1.0 / std::sqrt(1.4)}};
    for (const auto& [l1, l2] : boundary) {
      const double i = l1 * l1 + l2 * l2, j = l1 * l1 * l2 * l2;
      // The normal of the boundary in (I, J) is not needed: step both ways in both variables.
      for (const auto& d : {std::pair{h, 0.0}, std::pair{0.0, h}}) {
        const auto a = at(i - d.first, j - d.second), b = at(i + d.first, j + d.second);
        // Each side's value carried to the boundary by its own slope: equal to O(h^2).
        const double from_a = a.w + d.first * a.w_i + d.second * a.w_j;
        const double from_b = b.w - d.first * b.w_i - d.second * b.w_j;
        EXPECT_NEAR(from_a, from_b, 1e-6 * k.c1 * h) << to_string(law) << l1;
        EXPECT_NEAR(a.w_i, b.w_i, 1e-5 * k.c1) << to_string(law) << l1;
        EXPECT_NEAR(a.w_j, b.w_j, 1e-5 * k.c1) << to_string(law) << l1;
      }
    }
  }
}

// A triangle at principal stretches (l1, l2) along axes turned by `angle`, bent out of plane.
Points stretched(const std::array<Vec3, 3>& rest, double l1, double l2, double angle) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Eigen::Matrix2d f = r * Eigen::Vector2d(l1, l2).asDiagonal() * r.transpose();
  Points x(3, 3);
  for (int k = 0; k < 3; ++k) {
    x.col(k).head<2>() = f * rest[static_cast<size_t>(k)].head<2>();
    x(2, k) = 0.0;
  }
  return x;
}

// Forces against central differences of the energy, the Hessian against central differences of
// the forces (relative 1e-6), in each state (slack, wrinkled, taut) away from their boundaries,
// turned and tilted, both laws, with the residual share; the projected Hessian semi-definite.
TEST(RelaxedMembrane, GradientAndHessianMatchFiniteDifferencesInEveryState) {
  const std::array<Vec3, 3> rest = {Vec3(0, 0, 0), Vec3(0.01, 0.001, 0), Vec3(0.002, 0.009, 0)};
  const std::array<std::pair<double, double>, 3> states = {std::pair{0.8, 0.7}, std::pair{1.5, 0.6},
                                                           std::pair{1.4, 1.2}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (MembraneLaw law : {MembraneLaw::neo_hookean, MembraneLaw::mooney_rivlin})
    for (const auto& [l1, l2] : states) {
      MembraneTriangles t;
      t.add({0, 1, 2}, rest[0], rest[1], rest[2], relaxed(law), kT);
      Points x = stretched(rest, l1, l2, 0.4);
      x.row(2) = Eigen::RowVector3d(0.0, 0.001, -0.0005);  // tilted, metric barely changed
      for (int c = 0; c < 9; ++c) x(c % 3, c / 3) += 1e-5 * u(rng);
      const std::string what = std::string(to_string(law)) + " l1 " + std::to_string(l1);
      expect_kernel_matches_finite_differences(t, x, what.c_str());
    }
}

// A wrinkled triangle carries uniaxial tension along its stretch and (but for the residual
// share) nothing across it: its largest principal stress is the law's uniaxial stress, its
// force across the compressed direction the residual's. A slack one carries only the residual.
TEST(RelaxedMembrane, AWrinkledTriangleCarriesUniaxialTension) {
  const std::array<Vec3, 3> rest = {Vec3(0, 0, 0), Vec3(0.01, 0.0, 0), Vec3(0.0, 0.01, 0)};
  const LawConstants full = law_constants(MembraneLaw::neo_hookean, kE);
  const double l = 1.5, lateral = 0.6;
  MembraneTriangles relaxed_t, full_t;
  relaxed_t.add({0, 1, 2}, rest[0], rest[1], rest[2], relaxed(MembraneLaw::neo_hookean), kT);
  full_t.add({0, 1, 2}, rest[0], rest[1], rest[2], full, kT);
  const Points x = stretched(rest, l, lateral, 0.0);
  // Cauchy stress of uniaxial tension, over the natural thickness: nominal / lateral stretch.
  const double expected = uniaxial_nominal_stress(full, l) / lateral;
  EXPECT_NEAR(relaxed_t.stress(0, x, kT).stress / expected, 1.0, 2e-3);
  // Without the relaxation, the same triangle's lateral compression is far from free.
  Points f = Points::Zero(3, 3), g = Points::Zero(3, 3);
  relaxed_t.add_forces(x, nullptr, 0, 1, f);
  full_t.add_forces(x, nullptr, 0, 1, g);
  EXPECT_LT(std::abs(f(1, 2)), 2e-3 * std::abs(g(1, 2)));
  const Points slack = stretched(rest, 0.9, 0.8, 0.3);
  EXPECT_NEAR(relaxed_t.energy(0, slack), kRelaxedResidual * full_t.energy(0, slack),
              1e-12 * full_t.energy(0, slack));
}

// Names and the rule for which laws relax.
TEST(RelaxedMembrane, OnlyIncompressibleLawsRelax) {
  EXPECT_EQ(wrinkling_from_name("relaxed"), Wrinkling::relaxed);
  EXPECT_EQ(wrinkling_from_name("full"), Wrinkling::full);
  EXPECT_FALSE(wrinkling_from_name("wrinkled"));
  EXPECT_TRUE(relaxable(MembraneLaw::neo_hookean));
  EXPECT_TRUE(relaxable(MembraneLaw::mooney_rivlin));
  EXPECT_FALSE(relaxable(MembraneLaw::stvk));
  EXPECT_FALSE(relaxable(MembraneLaw::linear));
}

}  // namespace
}  // namespace relaxed_membrane_test
}  // namespace membra
