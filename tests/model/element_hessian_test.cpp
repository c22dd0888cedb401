// The elements' analytic Hessians (springs, turning-angle bending, bilayer hinges) against
// central differences of their analytic gradients, on random, compressed and nearly folded
// configurations: relative error below 1e-6 of the block's largest entry. The projected
// Hessians are positive semi-definite and equal the exact ones where those already are.
#include <array>
#include <random>

#include <gtest/gtest.h>

#include "membra/model/elements/bend_kernel.hpp"
#include "membra/model/elements/hinge_kernel.hpp"
#include "membra/model/elements/spring_kernel.hpp"

namespace membra {
namespace {

template <int N, typename Grad>
Eigen::Matrix<double, 3 * N, 3 * N> differenced(std::array<Vec3, N> p, double step, Grad grad) {
  Eigen::Matrix<double, 3 * N, 3 * N> h;
  for (int c = 0; c < 3 * N; ++c) {
    auto pp = p, pm = p;
    pp[static_cast<size_t>(c / 3)][c % 3] += step;
    pm[static_cast<size_t>(c / 3)][c % 3] -= step;
    const Eigen::Matrix<double, 3 * N, 1> gp = grad(pp), gm = grad(pm);
    h.col(c) = (gp - gm) / (2.0 * step);
  }
  return h;
}

template <typename M>
double relative_error(const M& analytic, const M& reference) {
  return (analytic - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

// Three configurations of an element's n particles (2: a spring, 3: a bending element along a
// line, 4: a hinge, two triangles on the edge 0-1), jittered: random, compressed (shrunk by 0.6
// along x), nearly folded (a bending element turned back by ~150 degrees, a hinge nearly closed).
std::vector<std::vector<Vec3>> configurations(int n, unsigned seed) {
  const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::vector<Vec3> hinge = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0)};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<std::vector<Vec3>> out;
  for (int kind = 0; kind < 3; ++kind) {
    std::vector<Vec3> p;
    for (int k = 0; k < n; ++k) {
      Vec3 q = (n == 4 ? hinge : line)[static_cast<size_t>(k)] + Vec3(u(rng), u(rng), u(rng));
      if (kind == 1) q.x() *= 0.6;
      p.push_back(q);
    }
    if (kind == 2 && n == 3) p[2] = p[0] + Vec3(0.3, 0.15, 0.05);
    if (kind == 2 && n == 4) p[3] = p[2] + Vec3(0.05, 0.1, 0.2);
    out.push_back(p);
  }
  return out;
}

TEST(ElementHessian, SpringMatchesDifferencesOfItsForce) {
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (const auto& p : configurations(2, seed))
      for (double l0 : {0.5, 1.0, 1.5}) {  // stretched, about natural, compressed
        const double k = 3.0e3;
        auto grad = [&](const std::array<Vec3, 2>& q) {
          Eigen::Matrix<double, 6, 1> g;
          const Vec3 fa = spring_static_force_on_a(q[0], q[1], l0, k);
          g << -fa, fa;
          return g;
        };
        const Eigen::Matrix3d kb = spring_hessian_block(p[0], p[1], l0, k);
        Eigen::Matrix<double, 6, 6> h;
        h << kb, -kb, -kb, kb;
        EXPECT_LT(relative_error(h, differenced<2>({p[0], p[1]}, 1e-6, grad)), 1e-6);
      }
}

TEST(ElementHessian, BendingMatchesDifferencesOfItsGradient) {
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (const auto& p : configurations(3, seed)) {
      const double c = 2.0e-3;
      auto grad = [&](const std::array<Vec3, 3>& q) {
        const BendEval e = bend_eval(q[0], q[1], q[2], c);
        Eigen::Matrix<double, 9, 1> g;
        g << e.grad[0], e.grad[1], e.grad[2];
        return g;
      };
      const BendHessian h = bend_hessian(p[0], p[1], p[2], c);
      EXPECT_LT(relative_error(h, differenced<3>({p[0], p[1], p[2]}, 1e-6, grad)), 1e-6)
          << "seed " << seed;
    }
}

TEST(ElementHessian, HingeMatchesDifferencesOfItsGradient) {
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (const auto& p : configurations(4, seed)) {
      const double moment = -4.0e-4;
      auto grad = [&](const std::array<Vec3, 4>& q) {
        const HingeEval e = hinge_eval(q[0], q[1], q[2], q[3]);
        Eigen::Matrix<double, 12, 1> g;
        g << e.grad[0], e.grad[1], e.grad[2], e.grad[3];
        return Eigen::Matrix<double, 12, 1>(moment * g);
      };
      const HingeHessian h = hinge_hessian(p[0], p[1], p[2], p[3], moment);
      EXPECT_LT(relative_error(h, differenced<4>({p[0], p[1], p[2], p[3]}, 1e-6, grad)), 1e-6)
          << "seed " << seed;
    }
}

TEST(ElementHessian, ProjectionIsPositiveSemiDefiniteAndKeepsConvexElements) {
  const std::array<Vec3, 3> bent = {Vec3(0, 0, 0), Vec3(0.6, 0, 0.2), Vec3(1.1, 0.1, 0.1)};
  const BendHessian h = bend_hessian(bent[0], bent[1], bent[2], 1.0);
  const BendHessian hp = bend_hessian(bent[0], bent[1], bent[2], 1.0, true);
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<BendHessian>(h).eigenvalues().minCoeff(),
            -1e-3 * h.norm());  // this configuration is not convex: the test means something
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<BendHessian>(hp).eigenvalues().minCoeff(),
            -1e-12 * hp.norm());
  // A compressed spring loses its negative transverse stiffness, a stretched one keeps all.
  const Eigen::Matrix3d compressed =
      spring_hessian_block(Vec3(0, 0, 0), Vec3(1, 0, 0), 1.5, 2.0, true);
  EXPECT_NEAR(compressed(1, 1), 0.0, 1e-15);
  EXPECT_NEAR(compressed(0, 0), 2.0, 1e-15);
  const Eigen::Matrix3d stretched = spring_hessian_block(Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 2.0);
  EXPECT_TRUE(
      stretched.isApprox(spring_hessian_block(Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 2.0, true)));
  EXPECT_NEAR(stretched(1, 1), 1.0, 1e-15);  // k (1 - l0/l)
}

}  // namespace
}  // namespace membra
