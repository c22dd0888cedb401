// Self-contact (model/elements/self_contact.hpp): the point-triangle distance against a brute
// force, the barrier's smoothness at the gap, the kernel's gradient against differences of its
// energy and its Hessian against differences of its gradient in every region of the triangle
// (relative 1e-6), and the set's gathering, exclusion and step limit.
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "membra/model/elements/self_contact.hpp"
#include "membra/model/model.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace self_contact_test {
namespace {

const Vec3 kA(0.0, 0.0, 0.0), kB(0.01, 0.0, 0.0), kC(0.003, 0.008, 0.0);  // m

// The distance by sampling the triangle finely: an upper bound within the sampling's spacing.
double sampled_distance(const Vec3& p) {
  double best = INFINITY;
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
      best = std::min(best, (p - (kA + u * (kB - kA) + v * (kC - kA))).norm());
    }
  return best;
}

// Points near each of the triangle's seven regions, within a 1 mm gap of it.
std::vector<Vec3> points_in_every_region() {
  return {Vec3(0.004, 0.003, 0.0006),     Vec3(0.005, -0.0004, 0.0005),
          Vec3(0.0068, 0.0045, 0.0004),   Vec3(0.0010, 0.004, -0.0005),
          Vec3(-0.0004, -0.0003, 0.0004), Vec3(0.0105, -0.0002, -0.0003),
          Vec3(0.003, 0.0085, 0.0005)};
}

TEST(SelfContactKernel, DistanceIsTheNearestPointOfTheTriangle) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.004, 0.014);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(u(rng), u(rng), 0.3 * u(rng));
    const double d = std::sqrt(point_triangle_distance(p, kA, kB, kC).d2);
    const double s = sampled_distance(p);
    EXPECT_LE(d, s + 1e-12);
    EXPECT_GE(d, s - 3e-5);  // the sampling's spacing, 25 um
  }
}

// A triangle crushed to a segment, or two of its corners together: the distance is to the
// segment, and the gradient finite.
TEST(SelfContactKernel, ACollapsedTriangleIsMeasuredByItsEdges) {
  const Vec3 a(0, 0, 0), b(0.01, 0, 0), p(0.004, 0.0003, 0.0004);
  for (const Vec3& c : {Vec3(0.005, 0, 0), Vec3(0.01, 0, 0), Vec3(0, 0, 0)}) {
    EXPECT_NEAR(std::sqrt(point_triangle_distance(p, a, b, c).d2), 5e-4, 1e-12);
    EXPECT_TRUE(contact_gradient(p, a, b, c, 1e9, 1e-6).allFinite());
    EXPECT_TRUE(contact_hessian(p, a, b, c, 1e9, 1e-6, true).allFinite());
  }
}

TEST(SelfContactKernel, BarrierVanishesSmoothlyAtTheGapAndGrowsWithoutBound) {
  const double g2 = 1e-6;
  const BarrierValue at = contact_barrier(g2 * (1.0 - 1e-6), g2);
  EXPECT_NEAR(at.value, 0.0, 1e-22);
  EXPECT_NEAR(at.first, 0.0, 1e-11);
  EXPECT_NEAR(at.second, 0.0, 1e-5);
  EXPECT_EQ(contact_barrier(2.0 * g2, g2).value, 0.0);
  // Near contact b ~ -g^4 ln(D / g^2): the energy grows like a logarithm, its push like 1 / D.
  EXPECT_NEAR(contact_barrier(1e-12 * g2, g2).value / contact_barrier(1e-6 * g2, g2).value, 2.0,
              1e-5);
  EXPECT_NEAR(contact_barrier(1e-12 * g2, g2).first / contact_barrier(1e-10 * g2, g2).first, 100.0,
              1e-6);
  EXPECT_LT(contact_barrier(0.25 * g2, g2).first, 0.0);  // pushes apart
}

using Four = std::array<Vec3, 4>;

// Central differences of f (a 12-vector, or a number as a 1-vector, of the point and the
// triangle's corners) in each of the 12 coordinates, as the columns of a matrix.
template <int Rows, typename F>
Eigen::Matrix<double, Rows, 12> differences(const Four& x, double h, F f) {
  Eigen::Matrix<double, Rows, 12> out;
  for (int c = 0; c < 12; ++c) {
    Four xp = x, xm = x;
    xp[static_cast<size_t>(c / 3)][c % 3] += h;
    xm[static_cast<size_t>(c / 3)][c % 3] -= h;
    out.col(c) = (f(xp) - f(xm)) / (2.0 * h);
  }
  return out;
}

TEST(SelfContactKernel, GradientMatchesDifferencesOfTheEnergy) {
  const double w = 1e9, g2 = 1e-6;
  for (const Vec3& p : points_in_every_region()) {
    const Four x = {p, kA, kB, kC};
    const ContactGradient g = contact_gradient(x[0], x[1], x[2], x[3], w, g2);
    ASSERT_GT(g.norm(), 0.0);
    const ContactGradient fd =
        differences<1>(x, 1e-8, [&](const Four& y) {
          return Eigen::Matrix<double, 1, 1>(contact_energy(y[0], y[1], y[2], y[3], w, g2));
        }).transpose();
    EXPECT_LT((g - fd).cwiseAbs().maxCoeff() / g.cwiseAbs().maxCoeff(), 1e-6) << p.transpose();
  }
}

TEST(SelfContactKernel, HessianMatchesDifferencesOfTheGradient) {
  const double w = 1e9, g2 = 1e-6;
  for (const Vec3& p : points_in_every_region()) {
    const Four x = {p, kA, kB, kC};
    const ContactHessian hx = contact_hessian(x[0], x[1], x[2], x[3], w, g2, false);
    const ContactHessian fd = differences<12>(
        x, 1e-9, [&](const Four& y) { return contact_gradient(y[0], y[1], y[2], y[3], w, g2); });
    EXPECT_LT((hx - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff(), 1e-6) << p.transpose();
    const ContactHessian projected = contact_hessian(x[0], x[1], x[2], x[3], w, g2, true);
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<ContactHessian>(projected).eigenvalues().minCoeff(),
              -1e-9 * projected.norm());
  }
}

// A small stiff triangle (three particles joined by springs) dropped from 10 gaps above a large
// pinned one, under gravity: nothing but the contact holds it, and Newton's first step, on a
// Hessian with no stiffness along z, would carry it far through the large triangle. It must come
// to rest above it, each corner at the height where the barrier's push equals its weight.
TEST(SelfContact, ATriangleDroppedOnAnotherRestsAboveItWhereThePushEqualsTheWeight) {
  const double gap = 1e-3, pressure = 1000.0, mass = 1e-4, g = 9.81;
  Model m;
  const std::array<Vec3, 6> at = {Vec3(-0.05, -0.05, 0),     Vec3(0.05, -0.05, 0),
                                  Vec3(0, 0.05, 0),          Vec3(-0.005, -0.003, 0.01),
                                  Vec3(0.005, -0.003, 0.01), Vec3(0, 0.006, 0.01)};
  for (const Vec3& x : at) m.add_particle(mass, x);
  for (int p = 0; p < 3; ++p) m.pin(p);
  for (int k = 0; k < 3; ++k) {
    const int a = 3 + k, b = 3 + (k + 1) % 3;
    m.added_springs.a.push_back(a);
    m.added_springs.b.push_back(b);
    const double len = (at[static_cast<size_t>(a)] - at[static_cast<size_t>(b)]).norm();
    m.added_springs.rest_length.push_back(len);
    m.added_springs.start_length.push_back(len);
    m.added_springs.stiffness.push_back(1000.0);
    m.added_springs.damping.push_back(0.0);
  }
  m.gravity = Vec3(0, 0, -g);
  Points rest = m.reference;
  rest.rightCols(3).row(0).array() += 1.0;  // far apart on the "natural sheet": not excluded
  m.self_contact.cover({Triangle(0, 1, 2), Triangle(3, 4, 5)}, rest, gap, pressure, 3 * gap);
  State s = State::at_rest(m);
  NewtonOptions o;
  o.force_scale = mass * g;
  o.tolerance = 1e-10;
  const SolveReport r = solve_newton(m, s, o);
  ASSERT_TRUE(r.converged) << r.message;
  // Each corner: weight m g against the push w (-b'(d^2)) 2 d, w = k A / gap^3, A a third of
  // the small triangle's area; the height found by bisection.
  const double area = 0.5 * (at[4] - at[3]).cross(at[5] - at[3]).norm() / 3.0;
  const double w = pressure * area / (gap * gap * gap);
  auto push = [&](double d) { return -w * contact_barrier(d * d, gap * gap).first * 2.0 * d; };
  double lo = 1e-9, hi = gap;
  for (int k = 0; k < 200; ++k) (push(0.5 * (lo + hi)) > mass * g ? lo : hi) = 0.5 * (lo + hi);
  for (int p = 3; p < 6; ++p) EXPECT_NEAR(s.x(2, p), lo, 1e-6 * lo) << p;
  const ContactReading c = m.self_contact.read(s.x);
  EXPECT_EQ(c.touching, 3);
  EXPECT_NEAR(c.push, 3.0 * mass * g, 1e-6 * mass * g);
}

// Gathering: pairs nearer than 1.5 gaps must be listed and a new list holds those nearer than 2;
// a point near a triangle that lies near it on the natural sheet too is excluded.
TEST(SelfContact, GathersNearPairsAndExcludesNeighboursOnTheNaturalSheet) {
  SelfContact c;
  Points x(3, 6);
  x.leftCols(3) << 0, 0.01, 0, 0, 0, 0.01, 0, 0, 0;
  x.rightCols(3) = x.leftCols(3);
  x.rightCols(3).row(2).array() += 0.0012;  // 1.2 gaps above
  Points rest = x;
  rest.rightCols(3).row(0).array() += 1.0;
  c.cover({Triangle(0, 1, 2), Triangle(3, 4, 5)}, rest, 1e-3, 1000.0, 3e-3);
  EXPECT_TRUE(c.refresh(x));
  EXPECT_EQ(c.size(), 6);      // each corner of each over (or under) the other triangle
  EXPECT_FALSE(c.refresh(x));  // nothing new
  // The same two triangles, neighbours on the natural sheet: no pair.
  c.cover({Triangle(0, 1, 2), Triangle(3, 4, 5)}, x, 1e-3, 1000.0, 3e-3);
  EXPECT_FALSE(c.refresh(x));
  EXPECT_EQ(c.size(), 0);
  EXPECT_THROW(c.cover({}, x, 0.0, 1000.0, 3e-3), std::invalid_argument);
  EXPECT_THROW(c.cover({}, x, 1e-3, 1000.0, 1.5e-3), std::invalid_argument);  // < 2 gaps
}

// The step limit: a triangle moving onto another by 3 gaps stops 1 gap away when the pair is
// not listed, and keeps a tenth of its distance when it is; a step that moves both alike is
// not limited at all.
TEST(SelfContact, StepLimitStopsApproachesAndLetsCommonMotionThrough) {
  SelfContact c;
  Points x(3, 6);
  x.leftCols(3) << 0, 0.01, 0, 0, 0, 0.01, 0, 0, 0;
  x.rightCols(3) = x.leftCols(3);
  x.rightCols(3).row(2).array() += 0.004;
  Points rest = x;
  rest.rightCols(3).row(0).array() += 1.0;
  c.cover({Triangle(0, 1, 2), Triangle(3, 4, 5)}, rest, 1e-3, 1000.0, 3e-3);
  c.refresh(x);
  ASSERT_EQ(c.size(), 0);
  Points down = Points::Zero(3, 6);
  down.rightCols(3).row(2).array() = -0.006;                 // through the lower one, 2 mm below it
  EXPECT_NEAR(c.step_limit(x, down, Points()), 0.5, 1e-12);  // 4 mm -> 1 mm: half the step
  Points together = Points::Zero(3, 6);
  together.row(2).array() = -0.05;
  EXPECT_EQ(c.step_limit(x, together, Points()), 1.0);
  x.rightCols(3).row(2).array() = 0.0012;
  ASSERT_TRUE(c.refresh(x));
  EXPECT_NEAR(c.step_limit(x, down, Points()), 0.9 * 0.0012 / 0.006, 1e-12);
}

}  // namespace
}  // namespace self_contact_test
}  // namespace membra
