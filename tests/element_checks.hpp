#pragma once
// Checks shared by the element and mechanics tests (they link membra).
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "membra/model/model.hpp"
#include "membra/solve/hessian_assembler.hpp"

namespace membra {

// Element 0 of `s` on particles 0..N-1 at positions x: its forces match central differences of
// its energy, and its Hessian central differences of its forces (relative 1e-6), and the
// projected Hessian is positive semi-definite.
template <class Set>
void expect_kernel_matches_finite_differences(const Set& s, const Points& x, const char* what) {
  constexpr int n = 3 * Set::kArity;
  const int cols = static_cast<int>(x.cols());
  Points f = Points::Zero(3, cols);
  s.add_forces(x, nullptr, 0, 1, f);
  const Eigen::Matrix<double, n, n> hess = s.hessian(0, x, false);
  const double step = 1e-7;
  for (int c = 0; c < n; ++c) {
    Points xp = x, xm = x;
    xp(c % 3, c / 3) += step;
    xm(c % 3, c / 3) -= step;
    EXPECT_NEAR(-f(c % 3, c / 3), (s.energy(0, xp) - s.energy(0, xm)) / (2.0 * step),
                1e-6 * f.norm())
        << what << " " << c;
    Points fp = Points::Zero(3, cols), fm = Points::Zero(3, cols);
    s.add_forces(xp, nullptr, 0, 1, fp);
    s.add_forces(xm, nullptr, 0, 1, fm);
    const Eigen::Matrix<double, n, 1> col = -(fp - fm).reshaped() / (2.0 * step);
    EXPECT_LT((hess.col(c) - col).norm(), 1e-6 * hess.norm()) << what << " " << c;
  }
  using Eigensolver = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, n, n>>;
  EXPECT_GE(Eigensolver(s.hessian(0, x, true)).eigenvalues().minCoeff(), -1e-9 * hess.norm())
      << what;
}

// The smallest eigenvalue of the energy's Hessian in the out-of-plane (z) coordinates of the
// free particles: negative once a flat sheet has buckled.
inline double smallest_out_of_plane_eigenvalue(const Model& m, const Points& x) {
  const Eigen::MatrixXd h = Eigen::MatrixXd(potential_hessian(m, x));
  std::vector<int> z;
  for (int p = 0; p < m.num_particles(); ++p)
    if (!m.pinned(p)) z.push_back(3 * p + 2);
  Eigen::MatrixXd hz(z.size(), z.size());
  for (size_t a = 0; a < z.size(); ++a)
    for (size_t b = 0; b < z.size(); ++b) hz(a, b) = h(z[a], z[b]);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hz).eigenvalues()(0);
}

}  // namespace membra
